// LabStore's contract (server/store/LabStore.h) on both back ends.
#include "StoreBackends.h"

#include "server/store/UnixTime.h"

#include <algorithm>
#include <mutex>
#include <set>
#include <stdexcept>

using namespace tlmhub::server;

namespace tlmhub::test {
namespace {

class LabStoreConformance : public StoreTest {
protected:
    LabStore& labs() { return store().labs(); }

    std::int64_t addClass(const User& owner, const std::string& code, const std::string& name = "Control 101")
    {
        const auto id = labs().createClass(owner.id, name, code);
        if (!id) throw std::runtime_error("cannot add class " + code);
        return *id;
    }
    void join(std::int64_t classId, const User& user, const char* role = kClassStudent)
    {
        if (!labs().setMember(classId, user.id, role)) throw std::runtime_error("cannot add " + user.username);
    }
    std::int64_t addAssignment(std::int64_t classId, const std::string& title = "Tune the servo",
                               std::int64_t opensAt = 1764700000)
    {
        AssignmentInfo info;
        info.classId = classId;
        info.title = title;
        info.instructions = "# Task\nSet **P**";
        info.editMode = "parameters";
        info.parameters = R"([{"name":"P.k","min":0,"max":100}])";
        info.opensAt = opensAt;
        info.dueAt = 1765000000;
        const auto id = labs().createAssignment(info, "<template/>", "");
        if (!id) throw std::runtime_error("cannot add assignment " + title);
        return *id;
    }
    std::int64_t addModel(const User& owner, const std::string& name = "my copy")
    {
        const auto id = store().models().create(owner.id, name, "<hopsanmodelfile/>", false);
        if (!id) throw std::runtime_error("cannot add a model of " + owner.username);
        return *id;
    }
    // A copy of `assignmentId` for `student`: a new model of theirs, linked. Returns the model id.
    std::int64_t addCopy(std::int64_t assignmentId, const User& student)
    {
        const std::int64_t model = addModel(student);
        if (!labs().createCopy(StudentCopy{assignmentId, student.id, model, 1, 0}))
            throw std::runtime_error("cannot add a copy for " + student.username);
        return model;
    }
    HandIn handInOf(std::int64_t assignmentId, const User& student, const std::string& hmf = "<frozen/>")
    {
        HandIn h;
        h.assignmentId = assignmentId;
        h.studentId = student.id;
        h.hmf = hmf;
        h.jobId = 77;
        h.handedInAt = 1764800000;
        h.score = 3;
        h.maxScore = 4;
        h.checkResults = R"([{"name":"Overshoot","passed":true}])";
        return h;
    }
    HandIn addHandIn(std::int64_t assignmentId, const User& student)
    {
        const auto stored = labs().addHandIn(handInOf(assignmentId, student));
        if (!stored) throw std::runtime_error("cannot hand in for " + student.username);
        return *stored;
    }
    // Deletes the user past the store (no store deletes users yet), with their models first:
    // models are not deleted with their owner.
    void deleteUser(const User& user)
    {
        const std::string enforceKeys = GetParam() == Backend::SQLite ? "PRAGMA foreign_keys=ON; " : "";
        const std::string id = std::to_string(user.id);
        db->exec(enforceKeys + "DELETE FROM models WHERE owner_id = " + id + "; DELETE FROM users WHERE id = " + id);
    }
};
TLMHUB_STORE_CONFORMANCE(LabStoreConformance);

std::vector<std::int64_t> idsOf(const std::vector<ClassInfo>& classes)
{
    std::vector<std::int64_t> ids;
    for (const auto& c : classes) ids.push_back(c.id);
    return ids;
}

std::vector<std::int64_t> idsOf(const std::vector<AssignmentInfo>& assignments)
{
    std::vector<std::int64_t> ids;
    for (const auto& a : assignments) ids.push_back(a.id);
    return ids;
}

std::vector<std::string> namesOf(const std::vector<ClassMember>& members)
{
    std::vector<std::string> names;
    for (const auto& m : members) names.push_back(m.username);
    return names;
}

std::vector<std::int64_t> attemptsOf(const std::vector<HandIn>& handIns)
{
    std::vector<std::int64_t> attempts;
    for (const auto& h : handIns) attempts.push_back(h.attempt);
    return attempts;
}

std::string everyByte()
{
    std::string bytes;
    for (int b = 0; b < 256; ++b) bytes.push_back(static_cast<char>(b));
    return bytes + std::string(3, '\0') + "end";
}

// ---- classes

TEST_P(LabStoreConformance, CreateClassMakesTheOwnerItsTeacher)
{
    const User teacher = addUser("tina", kRoleTeacher);
    const long long before = unixNow();
    const auto id = labs().createClass(teacher.id, "Regelteknik \xc3\xa5", "ABCDEFGHJKLM");
    const long long after = unixNow();
    ASSERT_TRUE(id);
    const auto info = labs().classInfo(*id);
    ASSERT_TRUE(info);
    EXPECT_EQ(info->id, *id);
    EXPECT_EQ(info->name, "Regelteknik \xc3\xa5");
    EXPECT_EQ(info->ownerId, teacher.id);
    EXPECT_EQ(info->joinCode, "ABCDEFGHJKLM");
    EXPECT_FALSE(info->archived);
    EXPECT_GE(info->createdAt, before);
    EXPECT_LE(info->createdAt, after);
    EXPECT_EQ(labs().memberRole(*id, teacher.id), std::optional<std::string>(kClassTeacher));
    const auto members = labs().members(*id);
    ASSERT_EQ(members.size(), 1u);
    EXPECT_EQ(members[0].classId, *id);
    EXPECT_EQ(members[0].userId, teacher.id);
    EXPECT_EQ(members[0].username, "tina");
    EXPECT_EQ(members[0].role, kClassTeacher);
    EXPECT_GE(members[0].joinedAt, before);
    const auto classes = labs().classesOf(teacher.id);
    ASSERT_EQ(classes.size(), 1u);
    EXPECT_EQ(classes[0].theClass.id, *id);
    EXPECT_EQ(classes[0].theClass.joinCode, "ABCDEFGHJKLM");
    EXPECT_EQ(classes[0].role, kClassTeacher);
    EXPECT_FALSE(labs().classInfo(*id + 1000));
}

TEST_P(LabStoreConformance, CreateClassRefusesATakenJoinCodeAndAMissingOwner)
{
    const User tina = addUser("tina", kRoleTeacher);
    const User tom = addUser("tom", kRoleTeacher);
    const auto first = addClass(tina, "CODE00000001");
    EXPECT_EQ(labs().createClass(tom.id, "Another", "CODE00000001"), std::nullopt);
    EXPECT_EQ(labs().createClass(4242, "Orphan", "CODE00000002"), std::nullopt);
    EXPECT_EQ(idsOf(labs().listClasses()), (std::vector<std::int64_t>{first}));
    EXPECT_TRUE(labs().classesOf(tom.id).empty()) << "a refused class left its teacher member";
    EXPECT_TRUE(labs().classesOf(4242).empty());
    EXPECT_EQ(labs().classInfo(first)->ownerId, tina.id);
    // The code refused to the orphan is free.
    EXPECT_TRUE(labs().createClass(tom.id, "Another", "CODE00000002"));
}

TEST_P(LabStoreConformance, ClassByJoinCodeFindsOnlyThatCode)
{
    const User tina = addUser("tina", kRoleTeacher);
    const auto a = addClass(tina, "AAAAAAAAAAAA");
    const auto b = addClass(tina, "BBBBBBBBBBBB");
    EXPECT_EQ(labs().classByJoinCode("AAAAAAAAAAAA")->id, a);
    EXPECT_EQ(labs().classByJoinCode("BBBBBBBBBBBB")->id, b);
    EXPECT_EQ(labs().classByJoinCode("BBBBBBBBBBBB")->name, "Control 101");
    EXPECT_FALSE(labs().classByJoinCode("CCCCCCCCCCCC"));
    EXPECT_FALSE(labs().classByJoinCode(""));
    EXPECT_FALSE(labs().classByJoinCode("AAAAAAAAAAA"));
}

TEST_P(LabStoreConformance, ListClassesIsByIdAndClassesOfGivesTheRoles)
{
    const User tina = addUser("tina", kRoleTeacher);
    const User tom = addUser("tom", kRoleTeacher);
    const User sam = addUser("sam");
    const auto c1 = addClass(tina, "C1C1C1C1C1C1");
    const auto c2 = addClass(tom, "C2C2C2C2C2C2");
    const auto c3 = addClass(tina, "C3C3C3C3C3C3");
    EXPECT_EQ(idsOf(labs().listClasses()), (std::vector<std::int64_t>{c1, c2, c3}));
    join(c3, sam, kClassStudent);
    join(c2, sam, kClassAssistant);
    const auto ofSam = labs().classesOf(sam.id);
    ASSERT_EQ(ofSam.size(), 2u);
    EXPECT_EQ(ofSam[0].theClass.id, c2);
    EXPECT_EQ(ofSam[0].theClass.ownerId, tom.id);
    EXPECT_EQ(ofSam[0].role, kClassAssistant);
    EXPECT_EQ(ofSam[1].theClass.id, c3);
    EXPECT_EQ(ofSam[1].role, kClassStudent);
    const auto ofTina = labs().classesOf(tina.id);
    ASSERT_EQ(ofTina.size(), 2u);
    EXPECT_EQ(ofTina[0].theClass.id, c1);
    EXPECT_EQ(ofTina[1].theClass.id, c3);
}

TEST_P(LabStoreConformance, ArchiveAndRenameChangeOnlyThatClass)
{
    const User tina = addUser("tina", kRoleTeacher);
    const auto a = addClass(tina, "AAAAAAAAAAAA", "A");
    const auto b = addClass(tina, "BBBBBBBBBBBB", "B");
    EXPECT_TRUE(labs().setArchived(a, true));
    EXPECT_TRUE(labs().classInfo(a)->archived);
    EXPECT_FALSE(labs().classInfo(b)->archived);
    EXPECT_TRUE(labs().classesOf(tina.id)[0].theClass.archived);
    EXPECT_TRUE(labs().setArchived(a, false));
    EXPECT_FALSE(labs().classInfo(a)->archived);
    EXPECT_TRUE(labs().renameClass(b, "Reglerteknik \xe2\x80\x93 HT26"));
    EXPECT_EQ(labs().classInfo(b)->name, "Reglerteknik \xe2\x80\x93 HT26");
    EXPECT_EQ(labs().classInfo(a)->name, "A");
    EXPECT_FALSE(labs().setArchived(b + 1000, true));
    EXPECT_FALSE(labs().renameClass(b + 1000, "x"));
}

// ---- members

TEST_P(LabStoreConformance, SetMemberAddsAMemberAndChangesARole)
{
    const User tina = addUser("tina", kRoleTeacher);
    const User sam = addUser("sam");
    const auto id = addClass(tina, "CODE00000001");
    EXPECT_EQ(labs().memberRole(id, sam.id), std::nullopt);
    EXPECT_TRUE(labs().setMember(id, sam.id, kClassStudent));
    EXPECT_EQ(labs().memberRole(id, sam.id), std::optional<std::string>(kClassStudent));
    const auto joinedAt = labs().members(id)[0].joinedAt;   // sam < tina
    waitForNextSecond();
    EXPECT_TRUE(labs().setMember(id, sam.id, kClassAssistant));
    EXPECT_EQ(labs().memberRole(id, sam.id), std::optional<std::string>(kClassAssistant));
    const auto members = labs().members(id);
    ASSERT_EQ(members.size(), 2u) << "a role change added a member";
    EXPECT_EQ(members[0].username, "sam");
    EXPECT_EQ(members[0].role, kClassAssistant);
    EXPECT_EQ(members[0].joinedAt, joinedAt) << "a role change is not a new join";
    EXPECT_TRUE(labs().setMember(id, sam.id, kClassTeacher));
    EXPECT_EQ(labs().memberRole(id, sam.id), std::optional<std::string>(kClassTeacher));
    EXPECT_EQ(labs().classesOf(sam.id)[0].role, kClassTeacher);
}

TEST_P(LabStoreConformance, SetMemberRefusesAMissingClassOrUser)
{
    const User tina = addUser("tina", kRoleTeacher);
    const User sam = addUser("sam");
    const auto id = addClass(tina, "CODE00000001");
    EXPECT_FALSE(labs().setMember(id + 1000, sam.id, kClassStudent));
    EXPECT_FALSE(labs().setMember(id, 4242, kClassStudent));
    EXPECT_EQ(labs().members(id).size(), 1u);
    EXPECT_TRUE(labs().classesOf(sam.id).empty());
}

TEST_P(LabStoreConformance, MembersAreByUserNameAsBytes)
{
    const User tina = addUser("tina", kRoleTeacher);
    const auto id = addClass(tina, "CODE00000001");
    const auto other = addClass(tina, "CODE00000002");
    for (const char* name : {"carol", "Zoe", "bob", "alice"}) join(id, addUser(name));
    join(other, addUser("dave"));
    // Byte order on both back ends: capitals before small letters, whatever the locale.
    EXPECT_EQ(namesOf(labs().members(id)), (std::vector<std::string>{"Zoe", "alice", "bob", "carol", "tina"}));
    EXPECT_EQ(namesOf(labs().members(other)), (std::vector<std::string>{"dave", "tina"}));
    EXPECT_TRUE(labs().members(id + 1000).empty());
}

TEST_P(LabStoreConformance, RemoveMemberEndsTheMembership)
{
    const User tina = addUser("tina", kRoleTeacher);
    const User sam = addUser("sam");
    const auto id = addClass(tina, "CODE00000001");
    join(id, sam);
    EXPECT_TRUE(labs().removeMember(id, sam.id));
    EXPECT_EQ(labs().memberRole(id, sam.id), std::nullopt);
    EXPECT_TRUE(labs().classesOf(sam.id).empty());
    EXPECT_EQ(namesOf(labs().members(id)), (std::vector<std::string>{"tina"}));
    EXPECT_FALSE(labs().removeMember(id, sam.id)) << "gone already";
    EXPECT_FALSE(labs().removeMember(id + 1000, tina.id));
    // Joining again is a new membership.
    EXPECT_TRUE(labs().setMember(id, sam.id, kClassStudent));
    EXPECT_EQ(labs().memberRole(id, sam.id), std::optional<std::string>(kClassStudent));
}

TEST_P(LabStoreConformance, SupervisesCopyOnlyForStaffOfTheCopysClassWhileItsOwnerIsAStudent)
{
    const User tina = addUser("tina", kRoleTeacher);
    const User tom = addUser("tom", kRoleTeacher);
    const User anna = addUser("anna");   // assistant
    const User sam = addUser("sam");
    const User sue = addUser("sue");
    const User nobody = addUser("nobody");
    const auto lab = addClass(tina, "CODE00000001");
    const auto otherLab = addClass(tom, "CODE00000002");
    join(lab, anna, kClassAssistant);
    join(lab, sam);
    join(lab, sue);
    join(otherLab, sam);   // sam is tom's student too, but not in this assignment's class
    const auto assignment = addAssignment(lab);
    const auto samsCopy = addCopy(assignment, sam);
    const auto samsOwnModel = addModel(sam, "not a copy");

    EXPECT_TRUE(labs().supervisesCopy(tina.id, samsCopy)) << "the teacher";
    EXPECT_TRUE(labs().supervisesCopy(anna.id, samsCopy)) << "an assistant";
    EXPECT_FALSE(labs().supervisesCopy(tom.id, samsCopy)) << "another class's teacher";
    EXPECT_FALSE(labs().supervisesCopy(sue.id, samsCopy)) << "a fellow student";
    EXPECT_FALSE(labs().supervisesCopy(sam.id, samsCopy)) << "the student";
    EXPECT_FALSE(labs().supervisesCopy(nobody.id, samsCopy)) << "no member";
    EXPECT_FALSE(labs().supervisesCopy(tina.id, samsOwnModel)) << "a model that is no copy";
    EXPECT_FALSE(labs().supervisesCopy(tina.id, samsCopy + 1000)) << "no such model";

    // Staff who stop being staff stop supervising.
    ASSERT_TRUE(labs().setMember(lab, anna.id, kClassStudent));
    EXPECT_FALSE(labs().supervisesCopy(anna.id, samsCopy)) << "an assistant made a student";
    // A student made an assistant is no student: their copy is nobody's to supervise.
    ASSERT_TRUE(labs().setMember(lab, sam.id, kClassAssistant));
    EXPECT_FALSE(labs().supervisesCopy(tina.id, samsCopy));
    ASSERT_TRUE(labs().setMember(lab, sam.id, kClassStudent));
    EXPECT_TRUE(labs().supervisesCopy(tina.id, samsCopy));
    // A removed student's copy neither.
    ASSERT_TRUE(labs().removeMember(lab, sam.id));
    EXPECT_FALSE(labs().supervisesCopy(tina.id, samsCopy)) << "a removed student";
    ASSERT_TRUE(labs().copyByModel(samsCopy)) << "the copy's link stays";
}

// ---- assignments

TEST_P(LabStoreConformance, CreateAssignmentStoresItAtTemplateVersionOne)
{
    const User tina = addUser("tina", kRoleTeacher);
    const auto lab = addClass(tina, "CODE00000001");
    AssignmentInfo info;
    info.classId = lab;
    info.title = "Tune the servo \xc3\xa4";
    info.instructions = "# Task\nSet **P** so that ...\n";
    info.editMode = "free";
    info.parameters = "[]";
    info.opensAt = 1764700000;
    info.dueAt = 0;
    info.templateVersion = 9;   // ignored
    info.hasSolution = true;    // ignored
    const long long before = unixNow();
    const auto id = labs().createAssignment(info, "<template text/>", "<solution text/>");
    ASSERT_TRUE(id);
    const auto stored = labs().assignment(*id);
    ASSERT_TRUE(stored);
    EXPECT_EQ(stored->id, *id);
    EXPECT_EQ(stored->classId, lab);
    EXPECT_EQ(stored->title, info.title);
    EXPECT_EQ(stored->instructions, info.instructions);
    EXPECT_EQ(stored->editMode, "free");
    EXPECT_EQ(stored->parameters, "[]");
    EXPECT_EQ(stored->opensAt, 1764700000);
    EXPECT_EQ(stored->dueAt, 0);
    EXPECT_EQ(stored->templateVersion, 1);
    EXPECT_FALSE(stored->hasSolution) << "a solution without its reference result";
    EXPECT_GE(stored->createdAt, before);
    EXPECT_EQ(stored->updatedAt, stored->createdAt);
    EXPECT_EQ(labs().templateHmf(*id), std::optional<std::string>("<template text/>"));
    EXPECT_EQ(labs().solutionHmf(*id), std::optional<std::string>("<solution text/>"));
    EXPECT_EQ(labs().referenceResult(*id), std::nullopt);

    const auto without = addAssignment(lab);
    EXPECT_EQ(labs().solutionHmf(without), std::nullopt);
    EXPECT_EQ(labs().assignment(without)->parameters, R"([{"name":"P.k","min":0,"max":100}])");

    info.classId = lab + 1000;
    EXPECT_EQ(labs().createAssignment(info, "<t/>", ""), std::nullopt) << "no such class";
    EXPECT_FALSE(labs().assignment(*id + 1000));
    EXPECT_FALSE(labs().templateHmf(*id + 1000));
    EXPECT_FALSE(labs().solutionHmf(*id + 1000));
}

TEST_P(LabStoreConformance, AssignmentsOfAClassAreByOpeningTimeThenId)
{
    const User tina = addUser("tina", kRoleTeacher);
    const auto lab = addClass(tina, "CODE00000001");
    const auto other = addClass(tina, "CODE00000002");
    const auto late = addAssignment(lab, "late", 300);
    const auto early = addAssignment(lab, "early", 100);
    const auto middle1 = addAssignment(lab, "middle 1", 200);
    const auto elsewhere = addAssignment(other, "elsewhere", 50);
    const auto middle2 = addAssignment(lab, "middle 2", 200);
    EXPECT_EQ(idsOf(labs().assignmentsOf(lab)), (std::vector<std::int64_t>{early, middle1, middle2, late}));
    EXPECT_EQ(idsOf(labs().assignmentsOf(other)), (std::vector<std::int64_t>{elsewhere}));
    EXPECT_TRUE(labs().assignmentsOf(other + 1000).empty());
}

TEST_P(LabStoreConformance, UpdateAssignmentChangesItsFieldsButNotTheTemplate)
{
    const User tina = addUser("tina", kRoleTeacher);
    const auto lab = addClass(tina, "CODE00000001");
    const auto id = addAssignment(lab);
    const auto created = *labs().assignment(id);
    waitForNextSecond();
    AssignmentInfo change = created;
    change.classId = lab + 1000;   // not changed by an update
    change.title = "Tune the servo again";
    change.instructions = "new";
    change.editMode = "free";
    change.parameters = "[]";
    change.opensAt = 1;
    change.dueAt = 2;
    change.templateVersion = 42;
    EXPECT_TRUE(labs().updateAssignment(change));
    const auto updated = *labs().assignment(id);
    EXPECT_EQ(updated.classId, lab);
    EXPECT_EQ(updated.title, "Tune the servo again");
    EXPECT_EQ(updated.instructions, "new");
    EXPECT_EQ(updated.editMode, "free");
    EXPECT_EQ(updated.parameters, "[]");
    EXPECT_EQ(updated.opensAt, 1);
    EXPECT_EQ(updated.dueAt, 2);
    EXPECT_EQ(updated.templateVersion, 1);
    EXPECT_EQ(updated.createdAt, created.createdAt);
    EXPECT_GT(updated.updatedAt, created.updatedAt);
    EXPECT_EQ(labs().templateHmf(id), std::optional<std::string>("<template/>"));
    change.id = id + 1000;
    EXPECT_FALSE(labs().updateAssignment(change));
}

TEST_P(LabStoreConformance, SetTemplateReplacesItAndCountsTheVersionUp)
{
    const User tina = addUser("tina", kRoleTeacher);
    const auto lab = addClass(tina, "CODE00000001");
    const auto id = addAssignment(lab);
    const auto other = addAssignment(lab);
    EXPECT_EQ(labs().setTemplate(id, "<template 2/>"), std::optional<std::int64_t>(2));
    EXPECT_EQ(labs().setTemplate(id, "<template 3/>"), std::optional<std::int64_t>(3));
    EXPECT_EQ(labs().templateHmf(id), std::optional<std::string>("<template 3/>"));
    EXPECT_EQ(labs().assignment(id)->templateVersion, 3);
    EXPECT_EQ(labs().assignment(other)->templateVersion, 1);
    EXPECT_EQ(labs().templateHmf(other), std::optional<std::string>("<template/>"));
    EXPECT_EQ(labs().setTemplate(id + 1000, "<t/>"), std::nullopt);
}

TEST_P(LabStoreConformance, TemplatesSetAtOnceGetDistinctVersions)
{
    const User tina = addUser("tina", kRoleTeacher);
    const auto id = addAssignment(addClass(tina, "CODE00000001"));
    std::mutex mutex;
    std::set<std::int64_t> versions;
    runAtOnce(4, [&](int i) {
        const auto version = labs().setTemplate(id, "<template " + std::to_string(i) + "/>");
        std::lock_guard lock(mutex);
        if (version) versions.insert(*version);
    });
    EXPECT_EQ(versions, (std::set<std::int64_t>{2, 3, 4, 5}));
    EXPECT_EQ(labs().assignment(id)->templateVersion, 5);
}

TEST_P(LabStoreConformance, SolutionAndReferenceResultAreStoredTogether)
{
    const User tina = addUser("tina", kRoleTeacher);
    const auto lab = addClass(tina, "CODE00000001");
    const auto id = addAssignment(lab);
    const auto other = addAssignment(lab);
    const std::string blob = everyByte();
    EXPECT_TRUE(labs().setSolution(id, "<solution/>", blob));
    EXPECT_TRUE(labs().assignment(id)->hasSolution);
    EXPECT_EQ(labs().solutionHmf(id), std::optional<std::string>("<solution/>"));
    EXPECT_EQ(labs().referenceResult(id), std::optional<std::string>(blob)) << "bytes lost (zero bytes?)";
    EXPECT_FALSE(labs().assignment(other)->hasSolution);
    EXPECT_EQ(labs().referenceResult(other), std::nullopt);

    const std::string large(200'000, '\x01');
    EXPECT_TRUE(labs().setSolution(id, "<solution 2/>", large));
    EXPECT_EQ(labs().solutionHmf(id), std::optional<std::string>("<solution 2/>"));
    EXPECT_EQ(labs().referenceResult(id), std::optional<std::string>(large));

    // An empty reference result is one, not none.
    EXPECT_TRUE(labs().setSolution(other, "<solution/>", ""));
    EXPECT_TRUE(labs().assignment(other)->hasSolution);
    EXPECT_EQ(labs().referenceResult(other), std::optional<std::string>(""));

    // No solution: neither.
    EXPECT_TRUE(labs().setSolution(id, "", "ignored"));
    EXPECT_FALSE(labs().assignment(id)->hasSolution);
    EXPECT_EQ(labs().solutionHmf(id), std::nullopt);
    EXPECT_EQ(labs().referenceResult(id), std::nullopt);

    EXPECT_FALSE(labs().setSolution(id + 1000, "<s/>", blob));
    EXPECT_EQ(labs().referenceResult(id + 1000), std::nullopt);
}

TEST_P(LabStoreConformance, RemoveAssignmentTakesItsChecksCopiesHandInsAndComments)
{
    const User tina = addUser("tina", kRoleTeacher);
    const User sam = addUser("sam");
    const auto lab = addClass(tina, "CODE00000001");
    join(lab, sam);
    const auto id = addAssignment(lab);
    const auto kept = addAssignment(lab);
    ASSERT_TRUE(labs().replaceChecks(id, {AssignmentCheck{0, "c", true, 1, "{}"}}));
    ASSERT_TRUE(labs().replaceChecks(kept, {AssignmentCheck{0, "k", true, 1, "{}"}}));
    const auto model = addCopy(id, sam);
    const auto keptModel = addCopy(kept, sam);
    const auto handIn = addHandIn(id, sam);
    const auto keptHandIn = addHandIn(kept, sam);
    ASSERT_TRUE(labs().addComment(handIn.id, tina.id, "good"));
    ASSERT_TRUE(labs().addComment(keptHandIn.id, tina.id, "kept"));

    EXPECT_TRUE(labs().removeAssignment(id));
    EXPECT_FALSE(labs().assignment(id));
    EXPECT_FALSE(labs().templateHmf(id));
    EXPECT_TRUE(labs().checks(id).empty());
    EXPECT_FALSE(labs().copy(id, sam.id));
    EXPECT_FALSE(labs().copyByModel(model));
    EXPECT_TRUE(labs().handIns(id, std::nullopt).empty());
    EXPECT_FALSE(labs().handIn(handIn.id));
    EXPECT_TRUE(labs().comments(handIn.id).empty());
    EXPECT_TRUE(store().models().summary(model)) << "the copy's model stays with its owner";
    EXPECT_FALSE(labs().removeAssignment(id)) << "gone already";

    EXPECT_EQ(labs().checks(kept).size(), 1u);
    EXPECT_EQ(labs().copyByModel(keptModel)->assignmentId, kept);
    EXPECT_TRUE(labs().handIn(keptHandIn.id));
    EXPECT_EQ(labs().comments(keptHandIn.id).size(), 1u);
}

// ---- checks

TEST_P(LabStoreConformance, ReplaceChecksReplacesAllInTheirOrder)
{
    const User tina = addUser("tina", kRoleTeacher);
    const auto lab = addClass(tina, "CODE00000001");
    const auto id = addAssignment(lab);
    const auto other = addAssignment(lab);
    EXPECT_TRUE(labs().checks(id).empty());
    const std::vector<AssignmentCheck> first{
        {0, "Position follows the reference", true, 2, R"({"kind":"curve","variable":"Mass#P1#x"})"},
        {1, "Overshoot", false, 0.1 + 0.2, R"({"kind":"scalar","measure":"overshoot","max":10})"},
        {2, "Settling \xc3\xa5", false, 1e-300, "{}"}};
    EXPECT_TRUE(labs().replaceChecks(id, first));
    auto stored = labs().checks(id);
    ASSERT_EQ(stored.size(), 3u);
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_EQ(stored[i].position, static_cast<std::int64_t>(i));
        EXPECT_EQ(stored[i].name, first[i].name);
        EXPECT_EQ(stored[i].pretest, first[i].pretest);
        EXPECT_EQ(stored[i].points, first[i].points) << "points not exact";
        EXPECT_EQ(stored[i].definition, first[i].definition);
    }
    ASSERT_TRUE(labs().replaceChecks(other, {AssignmentCheck{0, "other", true, 1, "{}"}}));

    // Fewer checks, in another order; their positions are the list's.
    const std::vector<AssignmentCheck> second{{0, "B", false, 1, "{}"}, {0, "A", true, 3, "{\"a\":1}"}};
    EXPECT_TRUE(labs().replaceChecks(id, second));
    stored = labs().checks(id);
    ASSERT_EQ(stored.size(), 2u);
    EXPECT_EQ(stored[0].name, "B");
    EXPECT_EQ(stored[0].position, 0);
    EXPECT_EQ(stored[1].name, "A");
    EXPECT_EQ(stored[1].position, 1);
    EXPECT_TRUE(stored[1].pretest);
    EXPECT_EQ(stored[1].points, 3);

    EXPECT_TRUE(labs().replaceChecks(id, {}));
    EXPECT_TRUE(labs().checks(id).empty());
    EXPECT_EQ(labs().checks(other).size(), 1u) << "another assignment's checks changed";
    EXPECT_FALSE(labs().replaceChecks(id + 1000, first));
    EXPECT_FALSE(labs().replaceChecks(id + 1000, {}));
    EXPECT_TRUE(labs().checks(id + 1000).empty());
}

TEST_P(LabStoreConformance, ChecksReplacedAtOnceAreOneWholeList)
{
    const User tina = addUser("tina", kRoleTeacher);
    const auto id = addAssignment(addClass(tina, "CODE00000001"));
    runAtOnce(4, [&](int i) {
        std::vector<AssignmentCheck> checks;
        for (int k = 0; k <= i; ++k) checks.push_back(AssignmentCheck{k, "list " + std::to_string(i), true, 1, "{}"});
        for (int round = 0; round < 5; ++round)
            if (!labs().replaceChecks(id, checks)) ADD_FAILURE() << "refused";
    });
    const auto stored = labs().checks(id);
    ASSERT_FALSE(stored.empty());
    EXPECT_EQ(stored.size(), static_cast<std::size_t>(std::stoi(stored[0].name.substr(5)) + 1));
    for (const auto& check : stored) EXPECT_EQ(check.name, stored[0].name) << "two lists mixed";
}

// ---- copies

TEST_P(LabStoreConformance, ACopyIsStoredOncePerStudentAndAssignment)
{
    const User tina = addUser("tina", kRoleTeacher);
    const User sam = addUser("sam");
    const User sue = addUser("sue");
    const auto lab = addClass(tina, "CODE00000001");
    const auto id = addAssignment(lab);
    const auto other = addAssignment(lab);
    const auto model = addModel(sam);
    const long long before = unixNow();
    EXPECT_TRUE(labs().createCopy(StudentCopy{id, sam.id, model, 1, 0}));
    const auto copy = labs().copy(id, sam.id);
    ASSERT_TRUE(copy);
    EXPECT_EQ(copy->assignmentId, id);
    EXPECT_EQ(copy->studentId, sam.id);
    EXPECT_EQ(copy->modelId, model);
    EXPECT_EQ(copy->templateVersion, 1);
    EXPECT_GE(copy->createdAt, before);
    EXPECT_LE(copy->createdAt, unixNow());
    EXPECT_EQ(labs().copyByModel(model)->studentId, sam.id);

    EXPECT_FALSE(labs().createCopy(StudentCopy{id, sam.id, addModel(sam), 1, 0})) << "a second copy";
    EXPECT_EQ(labs().copy(id, sam.id)->modelId, model);
    EXPECT_FALSE(labs().createCopy(StudentCopy{id, sue.id, model, 1, 0})) << "a model that is a copy already";
    EXPECT_FALSE(labs().createCopy(StudentCopy{other, sam.id, model, 1, 0})) << "a model that is a copy already";
    EXPECT_FALSE(labs().createCopy(StudentCopy{id + 1000, sue.id, addModel(sue), 1, 0})) << "no such assignment";
    EXPECT_FALSE(labs().createCopy(StudentCopy{id, 4242, addModel(sue), 1, 0})) << "no such student";
    EXPECT_FALSE(labs().createCopy(StudentCopy{id, sue.id, model + 1000, 1, 0})) << "no such model";
    EXPECT_FALSE(labs().copy(id, sue.id));
    EXPECT_FALSE(labs().copy(other, sam.id));
    EXPECT_FALSE(labs().copyByModel(model + 1000));
    // The same student may have a copy of another assignment.
    EXPECT_TRUE(labs().createCopy(StudentCopy{other, sam.id, addModel(sam), 3, 0}));
    EXPECT_EQ(labs().copy(other, sam.id)->templateVersion, 3);
}

TEST_P(LabStoreConformance, CopiesAreByStudentAndTheirTemplateVersionChanges)
{
    const User tina = addUser("tina", kRoleTeacher);
    const User sue = addUser("sue");
    const User sam = addUser("sam");
    const User bo = addUser("bo");
    const auto lab = addClass(tina, "CODE00000001");
    const auto id = addAssignment(lab);
    const auto other = addAssignment(lab);
    const auto samsModel = addCopy(id, sam);
    addCopy(id, sue);
    addCopy(id, bo);
    addCopy(other, sam);
    const auto copies = labs().copies(id);
    ASSERT_EQ(copies.size(), 3u);
    EXPECT_EQ(copies[0].studentId, sue.id);
    EXPECT_EQ(copies[1].studentId, sam.id);
    EXPECT_EQ(copies[1].modelId, samsModel);
    EXPECT_EQ(copies[2].studentId, bo.id);
    EXPECT_EQ(labs().copies(other).size(), 1u);
    EXPECT_TRUE(labs().copies(id + 1000).empty());

    EXPECT_TRUE(labs().setCopyTemplateVersion(id, sam.id, 4));
    EXPECT_EQ(labs().copy(id, sam.id)->templateVersion, 4);
    EXPECT_EQ(labs().copyByModel(samsModel)->templateVersion, 4);
    EXPECT_EQ(labs().copy(id, sue.id)->templateVersion, 1);
    EXPECT_EQ(labs().copy(other, sam.id)->templateVersion, 1);
    EXPECT_FALSE(labs().setCopyTemplateVersion(id, tina.id, 4)) << "no copy";
    EXPECT_FALSE(labs().setCopyTemplateVersion(id + 1000, sam.id, 4));
}

TEST_P(LabStoreConformance, RemovingACopysModelRemovesTheCopyButNotTheHandIns)
{
    const User tina = addUser("tina", kRoleTeacher);
    const User sam = addUser("sam");
    const auto lab = addClass(tina, "CODE00000001");
    join(lab, sam);
    const auto id = addAssignment(lab);
    const auto model = addCopy(id, sam);
    const auto handIn = addHandIn(id, sam);
    ASSERT_TRUE(labs().supervisesCopy(tina.id, model));
    ASSERT_TRUE(store().models().remove(model));
    EXPECT_FALSE(labs().copy(id, sam.id));
    EXPECT_FALSE(labs().copyByModel(model));
    EXPECT_TRUE(labs().copies(id).empty());
    EXPECT_FALSE(labs().supervisesCopy(tina.id, model));
    EXPECT_EQ(labs().handIn(handIn.id)->hmf, "<frozen/>") << "a hand-in keeps its own text";
    // The student may open the assignment again: a new copy.
    EXPECT_TRUE(labs().createCopy(StudentCopy{id, sam.id, addModel(sam), 1, 0}));
    EXPECT_EQ(labs().memberRole(lab, sam.id), std::optional<std::string>(kClassStudent));
}

// ---- hand-ins

TEST_P(LabStoreConformance, HandInsAreNumberedPerStudentAndAssignment)
{
    const User tina = addUser("tina", kRoleTeacher);
    const User sam = addUser("sam");
    const User sue = addUser("sue");
    const auto lab = addClass(tina, "CODE00000001");
    const auto id = addAssignment(lab);
    const auto other = addAssignment(lab);
    EXPECT_EQ(addHandIn(id, sam).attempt, 1);
    EXPECT_EQ(addHandIn(id, sue).attempt, 1);
    EXPECT_EQ(addHandIn(id, sam).attempt, 2);
    EXPECT_EQ(addHandIn(other, sam).attempt, 1);
    HandIn third = handInOf(id, sam, "<third/>");
    third.id = 999;       // ignored
    third.attempt = 17;   // ignored
    const auto stored = labs().addHandIn(third);
    ASSERT_TRUE(stored);
    EXPECT_NE(stored->id, 999);
    EXPECT_EQ(stored->attempt, 3);
    EXPECT_EQ(stored->hmf, "<third/>");
    EXPECT_EQ(attemptsOf(labs().handIns(id, sam.id)), (std::vector<std::int64_t>{3, 2, 1}));
    EXPECT_EQ(attemptsOf(labs().handIns(id, sue.id)), (std::vector<std::int64_t>{1}));
    EXPECT_EQ(attemptsOf(labs().handIns(other, sam.id)), (std::vector<std::int64_t>{1}));
}

TEST_P(LabStoreConformance, AHandInComesBackAsStoredWithItsStudentsName)
{
    const User tina = addUser("tina", kRoleTeacher);
    const User sam = addUser("sam \xc3\xa5");
    const auto id = addAssignment(addClass(tina, "CODE00000001"));
    HandIn h = handInOf(id, sam, std::string("<frozen copy \xc3\xa4/>\n") + std::string(100'000, 'x'));
    h.late = true;
    h.score = 0.1 + 0.2;
    h.maxScore = 7.25;
    h.checkResults = R"([{"name":"a","passed":false,"deviation":0.5}])";
    const auto stored = labs().addHandIn(h);
    ASSERT_TRUE(stored);
    for (const auto& got : {*stored, *labs().handIn(stored->id)}) {
        EXPECT_EQ(got.id, stored->id);
        EXPECT_EQ(got.assignmentId, id);
        EXPECT_EQ(got.studentId, sam.id);
        EXPECT_EQ(got.studentName, "sam \xc3\xa5");
        EXPECT_EQ(got.attempt, 1);
        EXPECT_EQ(got.hmf, h.hmf);
        EXPECT_EQ(got.jobId, std::optional<std::int64_t>(77));
        EXPECT_EQ(got.handedInAt, 1764800000);
        EXPECT_TRUE(got.late);
        EXPECT_EQ(got.score, 0.1 + 0.2) << "score not exact";
        EXPECT_EQ(got.maxScore, 7.25);
        EXPECT_EQ(got.checkResults, h.checkResults);
        EXPECT_EQ(got.grade, std::nullopt);
        EXPECT_EQ(got.gradedBy, std::nullopt);
    }
    // Lists leave the text out.
    const auto listed = labs().handIns(id, std::nullopt);
    ASSERT_EQ(listed.size(), 1u);
    EXPECT_EQ(listed[0].hmf, "");
    EXPECT_EQ(listed[0].studentName, "sam \xc3\xa5");
    EXPECT_EQ(listed[0].score, 0.1 + 0.2);
    EXPECT_TRUE(listed[0].late);
    EXPECT_EQ(listed[0].checkResults, h.checkResults);

    // No job, and no time given: now.
    HandIn bare = handInOf(id, sam);
    bare.jobId.reset();
    bare.handedInAt = 0;
    const long long before = unixNow();
    const auto second = labs().addHandIn(bare);
    ASSERT_TRUE(second);
    EXPECT_EQ(second->jobId, std::nullopt);
    EXPECT_FALSE(second->late);
    EXPECT_GE(second->handedInAt, before);
    EXPECT_LE(second->handedInAt, unixNow());
    EXPECT_EQ(labs().handIn(second->id)->jobId, std::nullopt);
    EXPECT_FALSE(labs().handIn(second->id + 1000));
}

TEST_P(LabStoreConformance, HandInsAreListedNewestFirstForTheAssignmentOrOneStudent)
{
    const User tina = addUser("tina", kRoleTeacher);
    const User sam = addUser("sam");
    const User sue = addUser("sue");
    const auto lab = addClass(tina, "CODE00000001");
    const auto id = addAssignment(lab);
    const auto other = addAssignment(lab);
    const auto h1 = addHandIn(id, sam).id;
    const auto h2 = addHandIn(id, sue).id;
    const auto h3 = addHandIn(id, sam).id;
    addHandIn(other, sue);
    std::vector<std::int64_t> ids;
    for (const auto& h : labs().handIns(id, std::nullopt)) ids.push_back(h.id);
    EXPECT_EQ(ids, (std::vector<std::int64_t>{h3, h2, h1}));
    ids.clear();
    for (const auto& h : labs().handIns(id, sam.id)) {
        ids.push_back(h.id);
        EXPECT_EQ(h.studentName, "sam");
    }
    EXPECT_EQ(ids, (std::vector<std::int64_t>{h3, h1}));
    EXPECT_TRUE(labs().handIns(id, tina.id).empty());
    EXPECT_TRUE(labs().handIns(id + 1000, std::nullopt).empty());
}

TEST_P(LabStoreConformance, AddHandInIsRefusedForAMissingAssignmentOrStudent)
{
    const User tina = addUser("tina", kRoleTeacher);
    const User sam = addUser("sam");
    const auto id = addAssignment(addClass(tina, "CODE00000001"));
    EXPECT_EQ(labs().addHandIn(handInOf(id + 1000, sam)), std::nullopt);
    HandIn ghost = handInOf(id, sam);
    ghost.studentId = 4242;
    EXPECT_EQ(labs().addHandIn(ghost), std::nullopt);
    EXPECT_TRUE(labs().handIns(id, std::nullopt).empty());
    EXPECT_EQ(addHandIn(id, sam).attempt, 1) << "a refused hand-in used up an attempt";
}

TEST_P(LabStoreConformance, HandInsAddedAtOnceGetDistinctAttempts)
{
    const User tina = addUser("tina", kRoleTeacher);
    const User sam = addUser("sam");
    const User sue = addUser("sue");
    const auto id = addAssignment(addClass(tina, "CODE00000001"));
    constexpr int kThreads = 8;
    std::mutex mutex;
    std::vector<std::int64_t> samsAttempts, suesAttempts;
    runAtOnce(kThreads, [&](int i) {
        const User& student = i % 4 == 3 ? sue : sam;   // six of sam's, two of sue's at once
        const auto stored = labs().addHandIn(handInOf(id, student, "<attempt of thread " + std::to_string(i) + "/>"));
        if (!stored) {
            ADD_FAILURE() << "thread " << i << ": refused";
            return;
        }
        std::lock_guard lock(mutex);
        (student.id == sam.id ? samsAttempts : suesAttempts).push_back(stored->attempt);
    });
    std::sort(samsAttempts.begin(), samsAttempts.end());
    std::sort(suesAttempts.begin(), suesAttempts.end());
    EXPECT_EQ(samsAttempts, (std::vector<std::int64_t>{1, 2, 3, 4, 5, 6}));
    EXPECT_EQ(suesAttempts, (std::vector<std::int64_t>{1, 2}));
    EXPECT_EQ(attemptsOf(labs().handIns(id, sam.id)), (std::vector<std::int64_t>{6, 5, 4, 3, 2, 1}));
    EXPECT_EQ(labs().handIns(id, std::nullopt).size(), static_cast<std::size_t>(kThreads));
}

TEST_P(LabStoreConformance, SetGradeSetsAndClearsTheGradeAndWhoGaveIt)
{
    const User tina = addUser("tina", kRoleTeacher);
    const User tom = addUser("tom", kRoleTeacher);
    const User sam = addUser("sam");
    const auto id = addAssignment(addClass(tina, "CODE00000001"));
    const auto h = addHandIn(id, sam);
    const auto other = addHandIn(id, sam);
    EXPECT_TRUE(labs().setGrade(h.id, 4.5, tina.id));
    auto graded = labs().handIn(h.id);
    EXPECT_EQ(graded->grade, std::optional<double>(4.5));
    EXPECT_EQ(graded->gradedBy, std::optional<std::int64_t>(tina.id));
    EXPECT_EQ(graded->score, 3) << "the checks' score stays";
    EXPECT_EQ(labs().handIns(id, sam.id)[1].grade, std::optional<double>(4.5));
    EXPECT_EQ(labs().handIn(other.id)->grade, std::nullopt);

    EXPECT_TRUE(labs().setGrade(h.id, 0.1 + 0.2, tom.id));
    graded = labs().handIn(h.id);
    EXPECT_EQ(graded->grade, std::optional<double>(0.1 + 0.2)) << "grade not exact";
    EXPECT_EQ(graded->gradedBy, std::optional<std::int64_t>(tom.id));
    EXPECT_TRUE(labs().setGrade(h.id, 0.0, tom.id));
    EXPECT_EQ(labs().handIn(h.id)->grade, std::optional<double>(0.0)) << "a zero grade is a grade";

    EXPECT_TRUE(labs().setGrade(h.id, std::nullopt, tina.id));
    graded = labs().handIn(h.id);
    EXPECT_EQ(graded->grade, std::nullopt);
    EXPECT_EQ(graded->gradedBy, std::nullopt);

    EXPECT_FALSE(labs().setGrade(h.id + 1000, 1.0, tina.id)) << "no such hand-in";
    EXPECT_FALSE(labs().setGrade(h.id, 1.0, 4242)) << "no such grader";
    EXPECT_EQ(labs().handIn(h.id)->grade, std::nullopt);
}

// ---- comments

TEST_P(LabStoreConformance, CommentsComeOldestFirstWithTheirAuthorsNames)
{
    const User tina = addUser("tina", kRoleTeacher);
    const User anna = addUser("anna");
    const User sam = addUser("sam");
    const auto id = addAssignment(addClass(tina, "CODE00000001"));
    const auto h = addHandIn(id, sam);
    const auto other = addHandIn(id, sam);
    const long long before = unixNow();
    const auto c1 = labs().addComment(h.id, tina.id, "Nice **curve**.");
    const auto c2 = labs().addComment(h.id, anna.id, "Check the overshoot \xe2\x80\x93 10 %.");
    const auto c3 = labs().addComment(other.id, tina.id, "elsewhere");
    const auto c4 = labs().addComment(h.id, tina.id, "");
    ASSERT_TRUE(c1 && c2 && c3 && c4);
    const auto comments = labs().comments(h.id);
    ASSERT_EQ(comments.size(), 3u);
    EXPECT_EQ(comments[0].id, *c1);
    EXPECT_EQ(comments[0].handInId, h.id);
    EXPECT_EQ(comments[0].authorId, tina.id);
    EXPECT_EQ(comments[0].authorName, "tina");
    EXPECT_EQ(comments[0].text, "Nice **curve**.");
    EXPECT_GE(comments[0].createdAt, before);
    EXPECT_LE(comments[0].createdAt, unixNow());
    EXPECT_EQ(comments[1].id, *c2);
    EXPECT_EQ(comments[1].authorName, "anna");
    EXPECT_EQ(comments[1].text, "Check the overshoot \xe2\x80\x93 10 %.");
    EXPECT_EQ(comments[2].id, *c4);
    EXPECT_EQ(comments[2].text, "");
    ASSERT_EQ(labs().comments(other.id).size(), 1u);
    EXPECT_EQ(labs().comments(other.id)[0].id, *c3);
    EXPECT_EQ(labs().addComment(h.id + 1000, tina.id, "x"), std::nullopt) << "no such hand-in";
    EXPECT_EQ(labs().addComment(h.id, 4242, "x"), std::nullopt) << "no such author";
    EXPECT_EQ(labs().comments(h.id).size(), 3u);
    EXPECT_TRUE(labs().comments(h.id + 1000).empty());
}

// ---- deleting

TEST_P(LabStoreConformance, RemoveClassTakesEverythingInItButNotTheModels)
{
    const User tina = addUser("tina", kRoleTeacher);
    const User sam = addUser("sam");
    const auto lab = addClass(tina, "CODE00000001");
    const auto kept = addClass(tina, "CODE00000002");
    join(lab, sam);
    join(kept, sam);
    const auto id = addAssignment(lab);
    const auto keptAssignment = addAssignment(kept);
    ASSERT_TRUE(labs().replaceChecks(id, {AssignmentCheck{0, "c", true, 1, "{}"}}));
    ASSERT_TRUE(labs().setSolution(id, "<s/>", everyByte()));
    const auto model = addCopy(id, sam);
    const auto keptModel = addCopy(keptAssignment, sam);
    const auto h = addHandIn(id, sam);
    const auto keptHandIn = addHandIn(keptAssignment, sam);
    ASSERT_TRUE(labs().addComment(h.id, tina.id, "gone with the class"));
    ASSERT_TRUE(labs().addComment(keptHandIn.id, tina.id, "kept"));

    EXPECT_TRUE(labs().removeClass(lab));
    EXPECT_FALSE(labs().classInfo(lab));
    EXPECT_FALSE(labs().classByJoinCode("CODE00000001"));
    EXPECT_TRUE(labs().members(lab).empty());
    EXPECT_EQ(labs().memberRole(lab, sam.id), std::nullopt);
    EXPECT_TRUE(labs().assignmentsOf(lab).empty());
    EXPECT_FALSE(labs().assignment(id));
    EXPECT_TRUE(labs().checks(id).empty());
    EXPECT_FALSE(labs().copyByModel(model));
    EXPECT_FALSE(labs().handIn(h.id));
    EXPECT_TRUE(labs().comments(h.id).empty());
    EXPECT_TRUE(store().models().summary(model)) << "the copy's model stays with its owner";
    EXPECT_FALSE(labs().removeClass(lab)) << "gone already";
    // Its join code is free again.
    EXPECT_TRUE(labs().createClass(tina.id, "again", "CODE00000001"));

    EXPECT_EQ(labs().classesOf(sam.id).size(), 1u);
    EXPECT_EQ(labs().classesOf(sam.id)[0].theClass.id, kept);
    EXPECT_EQ(labs().copyByModel(keptModel)->assignmentId, keptAssignment);
    EXPECT_EQ(labs().comments(keptHandIn.id).size(), 1u);
    EXPECT_TRUE(labs().supervisesCopy(tina.id, keptModel));
}

// No store deletes users yet; the schema already takes their lab rows with them.
TEST_P(LabStoreConformance, DeletingAStudentTakesTheirMembershipsCopiesHandInsAndComments)
{
    const User tina = addUser("tina", kRoleTeacher);
    const User sam = addUser("sam");
    const User sue = addUser("sue");
    const auto lab = addClass(tina, "CODE00000001");
    join(lab, sam);
    join(lab, sue);
    const auto id = addAssignment(lab);
    addCopy(id, sam);
    const auto suesModel = addCopy(id, sue);
    const auto samsHandIn = addHandIn(id, sam);
    const auto suesHandIn = addHandIn(id, sue);
    ASSERT_TRUE(labs().addComment(suesHandIn.id, sam.id, "sam's comment"));
    ASSERT_TRUE(labs().addComment(suesHandIn.id, tina.id, "tina's comment"));
    ASSERT_TRUE(labs().addComment(samsHandIn.id, tina.id, "on sam's"));

    deleteUser(sam);
    EXPECT_EQ(namesOf(labs().members(lab)), (std::vector<std::string>{"sue", "tina"}));
    EXPECT_TRUE(labs().classesOf(sam.id).empty());
    EXPECT_FALSE(labs().copy(id, sam.id));
    EXPECT_EQ(labs().copies(id).size(), 1u);
    EXPECT_FALSE(labs().handIn(samsHandIn.id));
    EXPECT_TRUE(labs().handIns(id, sam.id).empty());
    EXPECT_TRUE(labs().comments(samsHandIn.id).empty());
    const auto left = labs().comments(suesHandIn.id);
    ASSERT_EQ(left.size(), 1u);
    EXPECT_EQ(left[0].authorName, "tina");
    EXPECT_TRUE(labs().handIn(suesHandIn.id));
    EXPECT_TRUE(labs().supervisesCopy(tina.id, suesModel));
}

TEST_P(LabStoreConformance, DeletingStaffTakesTheirCommentsAndLeavesTheirGradesAndClasses)
{
    const User tina = addUser("tina", kRoleTeacher);
    const User tom = addUser("tom", kRoleTeacher);
    const User sam = addUser("sam");
    const auto lab = addClass(tina, "CODE00000001");
    join(lab, tom, kClassTeacher);
    join(lab, sam);
    const auto id = addAssignment(lab);
    const auto h = addHandIn(id, sam);
    ASSERT_TRUE(labs().setGrade(h.id, 5.0, tina.id));
    ASSERT_TRUE(labs().addComment(h.id, tina.id, "tina's"));
    ASSERT_TRUE(labs().addComment(h.id, tom.id, "tom's"));

    deleteUser(tina);
    const auto info = labs().classInfo(lab);
    ASSERT_TRUE(info) << "a class outlives its owner, with its other teachers";
    EXPECT_EQ(info->ownerId, 0);
    EXPECT_EQ(namesOf(labs().members(lab)), (std::vector<std::string>{"sam", "tom"}));
    const auto graded = labs().handIn(h.id);
    ASSERT_TRUE(graded);
    EXPECT_EQ(graded->grade, std::optional<double>(5.0)) << "the grade stays";
    EXPECT_EQ(graded->gradedBy, std::nullopt);
    const auto comments = labs().comments(h.id);
    ASSERT_EQ(comments.size(), 1u);
    EXPECT_EQ(comments[0].authorName, "tom");
    EXPECT_EQ(labs().listClasses().size(), 1u);
    EXPECT_EQ(labs().classesOf(tom.id).size(), 1u);
}

} // namespace
} // namespace tlmhub::test
