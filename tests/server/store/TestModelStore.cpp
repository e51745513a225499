// ModelStore's contract (server/store/ModelStore.h) on both back ends.
#include "StoreBackends.h"

#include "server/store/UnixTime.h"

#include <algorithm>

using namespace tlmhub::server;

namespace tlmhub::test {
namespace {

class ModelStoreConformance : public StoreTest {};
TLMHUB_STORE_CONFORMANCE(ModelStoreConformance);

std::vector<std::int64_t> idsOf(const std::vector<ModelSummary>& models)
{
    std::vector<std::int64_t> ids;
    for (const auto& m : models) ids.push_back(m.id);
    return ids;
}

TEST_P(ModelStoreConformance, CreateRefusesAnUnknownOwner)
{
    const User alice = addUser("alice");
    EXPECT_FALSE(store().models().create(alice.id + 1000, "orphan", "<hmf/>", false));
    EXPECT_TRUE(store().models().list().empty());
}

TEST_P(ModelStoreConformance, SummaryShowsNameOwnerExampleFlagAndTimes)
{
    const User teacher = addUser("tess", kRoleTeacher);
    const long long before = unixNow();
    const auto id = store().models().create(teacher.id, "Servo", "<hopsanmodelfile/>", true);
    const long long after = unixNow();
    ASSERT_TRUE(id);
    const auto s = store().models().summary(*id);
    ASSERT_TRUE(s);
    EXPECT_EQ(s->id, *id);
    EXPECT_EQ(s->name, "Servo");
    EXPECT_EQ(s->ownerId, teacher.id);
    EXPECT_EQ(s->ownerName, "tess");
    EXPECT_EQ(s->ownerRole, kRoleTeacher);
    EXPECT_TRUE(s->isExample);
    EXPECT_GE(s->createdAt, before);
    EXPECT_LE(s->createdAt, after);
    EXPECT_GE(s->updatedAt, s->createdAt);
    EXPECT_LE(s->updatedAt, after);
    EXPECT_FALSE(store().models().summary(*id + 1000));
}

TEST_P(ModelStoreConformance, SummaryFollowsTheOwnersCurrentRole)
{
    addUser("root", kRoleAdmin);
    const User u = addUser("u");
    const auto id = store().models().create(u.id, "m", "x", false);
    ASSERT_TRUE(id);
    User updated;
    UserChange promote;
    promote.role = kRoleTeacher;
    ASSERT_EQ(store().users().change(u.id, promote, updated), UserChangeOutcome::Changed);
    EXPECT_EQ(store().models().summary(*id)->ownerRole, kRoleTeacher);
}

TEST_P(ModelStoreConformance, HmfComesBackVerbatim)
{
    const User alice = addUser("alice");
    const std::string text = "<?xml version=\"1.0\"?>\r\n<hopsanmodelfile>\n\t<x a='1'>&amp; \\ %_ ''</x>\n</hopsanmodelfile>\n";
    const auto id = store().models().create(alice.id, "m", text, false);
    ASSERT_TRUE(id);
    EXPECT_EQ(store().models().hmf(*id), text);
    EXPECT_FALSE(store().models().hmf(*id + 1000));
    const auto empty = store().models().create(alice.id, "", "", false);
    ASSERT_TRUE(empty);
    EXPECT_EQ(store().models().hmf(*empty), "");
    EXPECT_EQ(store().models().summary(*empty)->name, "");
}

TEST_P(ModelStoreConformance, NamesNeedNotBeUnique)
{
    const User alice = addUser("alice");
    const auto a = store().models().create(alice.id, "same", "a", false);
    const auto b = store().models().create(alice.id, "same", "b", false);
    ASSERT_TRUE(a && b);
    EXPECT_NE(*a, *b);
    EXPECT_EQ(store().models().hmf(*a), "a");
    EXPECT_EQ(store().models().hmf(*b), "b");
}

TEST_P(ModelStoreConformance, UpdateChangesOnlyTheGivenFieldsAndTouchesUpdatedAt)
{
    const User alice = addUser("alice");
    const auto id = store().models().create(alice.id, "old name", "old text", false);
    ASSERT_TRUE(id);
    const ModelSummary created = *store().models().summary(*id);
    waitForNextSecond();
    ASSERT_TRUE(store().models().update(*id, std::string("new name"), std::nullopt));
    const ModelSummary renamed = *store().models().summary(*id);
    EXPECT_EQ(renamed.name, "new name");
    EXPECT_EQ(store().models().hmf(*id), "old text");
    EXPECT_EQ(renamed.createdAt, created.createdAt);
    EXPECT_GT(renamed.updatedAt, created.updatedAt);
    ASSERT_TRUE(store().models().update(*id, std::nullopt, std::string("new text")));
    EXPECT_EQ(store().models().summary(*id)->name, "new name");
    EXPECT_EQ(store().models().hmf(*id), "new text");
    EXPECT_EQ(store().models().summary(*id)->ownerId, alice.id);
    EXPECT_FALSE(store().models().update(*id + 1000, std::string("x"), std::string("y")));
}

TEST_P(ModelStoreConformance, RemoveDeletesOnlyThatModel)
{
    const User alice = addUser("alice");
    const auto a = store().models().create(alice.id, "a", "a", false);
    const auto b = store().models().create(alice.id, "b", "b", false);
    ASSERT_TRUE(a && b);
    EXPECT_TRUE(store().models().remove(*a));
    EXPECT_FALSE(store().models().summary(*a));
    EXPECT_FALSE(store().models().hmf(*a));
    EXPECT_FALSE(store().models().remove(*a));
    EXPECT_EQ(idsOf(store().models().list()), std::vector<std::int64_t>{*b});
}

TEST_P(ModelStoreConformance, ListIsInIdOrder)
{
    const User alice = addUser("alice");
    const User bob = addUser("bob", kRoleTeacher);
    std::vector<std::int64_t> ids;
    for (const char* name : {"zeta", "alpha", "mu"}) {
        ids.push_back(*store().models().create(alice.id, name, name, false));
        ids.push_back(*store().models().create(bob.id, name, name, true));
    }
    const auto list = store().models().list();
    EXPECT_EQ(idsOf(list), ids);
    EXPECT_TRUE(std::is_sorted(ids.begin(), ids.end()));
    ASSERT_EQ(list.size(), 6u);
    EXPECT_EQ(list[1].ownerName, "bob");
    EXPECT_EQ(list[1].ownerRole, kRoleTeacher);
    EXPECT_TRUE(list[1].isExample);
    EXPECT_EQ(list[2].name, "alpha");
}

TEST_P(ModelStoreConformance, ListVisibleToFollowsTheAccessPolicy)
{
    const User admin = addUser("admin", kRoleAdmin);
    const User teacher = addUser("teacher", kRoleTeacher);
    const User otherTeacher = addUser("teacher2", kRoleTeacher);
    const User student = addUser("student");
    const User otherStudent = addUser("student2");
    const auto make = [&](const User& owner, bool example) {
        return *store().models().create(owner.id, owner.username + (example ? " example" : ""), "x", example);
    };
    const std::int64_t adminOwn = make(admin, false), example = make(admin, true), teacherOwn = make(teacher, false),
                       otherTeacherOwn = make(otherTeacher, false), studentOwn = make(student, false),
                       otherStudentOwn = make(otherStudent, false), teacherExample = make(teacher, true);
    using Ids = std::vector<std::int64_t>;
    EXPECT_EQ(idsOf(store().models().listVisibleTo(admin)),
              (Ids{adminOwn, example, teacherOwn, otherTeacherOwn, studentOwn, otherStudentOwn, teacherExample}));
    // A teacher's role shows no one else's models (students' copies: through a class, LabAccess).
    EXPECT_EQ(idsOf(store().models().listVisibleTo(teacher)), (Ids{example, teacherOwn, teacherExample}));
    EXPECT_EQ(idsOf(store().models().listVisibleTo(student)), (Ids{example, studentOwn, teacherExample}));
    EXPECT_EQ(idsOf(store().models().listVisibleTo(otherStudent)), (Ids{example, otherStudentOwn, teacherExample}));
}

} // namespace
} // namespace tlmhub::test
