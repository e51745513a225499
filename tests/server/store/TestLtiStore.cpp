// LtiStore's contract (server/store/LtiStore.h) on both back ends: platforms with their
// deployments, unique by issuer and client id; a course mapped to one class even when first
// launches race; an assignment's line item per platform; and the score outbox: superseded
// scores, leases with numbers that fence a node whose lease was taken over, retries, giving up,
// and claims racing on several threads each getting different scores.
#include "StoreBackends.h"

#include <algorithm>
#include <mutex>
#include <set>

using namespace tlmhub::server;

namespace tlmhub::test {
namespace {

class LtiStoreConformance : public StoreTest {
protected:
    static LtiPlatform moodle(const std::string& clientId = "tool-1")
    {
        LtiPlatform platform;
        platform.name = "Moodle of the faculty";
        platform.issuer = "https://moodle.example.edu";
        platform.clientId = clientId;
        platform.authUrl = "https://moodle.example.edu/mod/lti/auth.php";
        platform.tokenUrl = "https://moodle.example.edu/mod/lti/token.php";
        platform.jwksUrl = "https://moodle.example.edu/mod/lti/certs.php";
        platform.deploymentIds = {"2", "1"};
        return platform;
    }
    std::int64_t addPlatform(const LtiPlatform& platform)
    {
        const auto id = store().lti().addPlatform(platform);
        if (!id) throw std::runtime_error("cannot add platform " + platform.clientId);
        return *id;
    }
    std::int64_t addClass(const User& owner, const std::string& code)
    {
        const auto id = store().labs().createClass(owner.id, "Hydraulics " + code, code);
        if (!id) throw std::runtime_error("cannot add class " + code);
        return *id;
    }
    std::int64_t addAssignment(std::int64_t classId)
    {
        AssignmentInfo info;
        info.classId = classId;
        info.title = "Tune the servo";
        info.editMode = "free";
        info.parameters = "[]";
        const auto id = store().labs().createAssignment(info, "<template/>", "");
        if (!id) throw std::runtime_error("cannot add an assignment");
        return *id;
    }
    // A score of `user` for `assignmentId` at the platform's line item 7.
    static LtiScore score(std::int64_t platformId, const User& user, std::int64_t assignmentId, double given)
    {
        LtiScore score;
        score.platformId = platformId;
        score.lineItemUrl = "https://moodle.example.edu/mod/lti/services.php/2/lineitems/7/lineitem";
        score.userSubject = "moodle-user-" + std::to_string(user.id);
        score.userId = user.id;
        score.assignmentId = assignmentId;
        score.scoreGiven = given;
        score.scoreMaximum = 10;
        score.comment = "checks: 3 of 4";
        score.timestampMs = 1765000000123;
        return score;
    }
};
TLMHUB_STORE_CONFORMANCE(LtiStoreConformance);

TEST_P(LtiStoreConformance, APlatformIsStoredWithItsDeploymentsAndUniqueByIssuerAndClientId)
{
    auto& lti = store().lti();
    const auto id = addPlatform(moodle());
    EXPECT_FALSE(lti.addPlatform(moodle())) << "the same issuer and client id again";
    const auto second = addPlatform(moodle("tool-2"));   // a second registration at the same platform

    const auto stored = lti.platform(id);
    ASSERT_TRUE(stored);
    EXPECT_EQ(stored->name, "Moodle of the faculty");
    EXPECT_EQ(stored->issuer, "https://moodle.example.edu");
    EXPECT_EQ(stored->clientId, "tool-1");
    EXPECT_EQ(stored->authUrl, "https://moodle.example.edu/mod/lti/auth.php");
    EXPECT_EQ(stored->tokenUrl, "https://moodle.example.edu/mod/lti/token.php");
    EXPECT_EQ(stored->jwksUrl, "https://moodle.example.edu/mod/lti/certs.php");
    EXPECT_EQ(stored->deploymentIds, (std::vector<std::string>{"1", "2"}));
    EXPECT_GT(stored->createdAt, 1700000000);

    const auto ofIssuer = lti.platformsOf("https://moodle.example.edu");
    ASSERT_EQ(ofIssuer.size(), 2U);
    EXPECT_EQ(ofIssuer[0].id, id);
    EXPECT_EQ(ofIssuer[1].id, second);
    EXPECT_TRUE(lti.platformsOf("https://canvas.example.edu").empty());
    EXPECT_EQ(lti.listPlatforms().size(), 2U);
    EXPECT_FALSE(lti.platform(second + 100));
}

TEST_P(LtiStoreConformance, AnUpdateReplacesTheDeploymentsButCannotTakeAnotherPlatformsIdentity)
{
    auto& lti = store().lti();
    const auto id = addPlatform(moodle());
    addPlatform(moodle("tool-2"));
    LtiPlatform changed = moodle();
    changed.id = id;
    changed.name = "Moodle 4.5";
    changed.jwksUrl = "https://moodle.example.edu/keys";
    changed.deploymentIds = {"3"};
    EXPECT_TRUE(lti.updatePlatform(changed));
    EXPECT_EQ(lti.platform(id)->name, "Moodle 4.5");
    EXPECT_EQ(lti.platform(id)->jwksUrl, "https://moodle.example.edu/keys");
    EXPECT_EQ(lti.platform(id)->deploymentIds, (std::vector<std::string>{"3"}));

    changed.clientId = "tool-2";   // the other registration's
    EXPECT_FALSE(lti.updatePlatform(changed));
    EXPECT_EQ(lti.platform(id)->clientId, "tool-1") << "unchanged";
    EXPECT_EQ(lti.platform(id)->deploymentIds, (std::vector<std::string>{"3"})) << "unchanged";
    changed.id = 999;
    changed.clientId = "tool-3";
    EXPECT_FALSE(lti.updatePlatform(changed)) << "no such platform";
}

TEST_P(LtiStoreConformance, ACourseIsMappedToTheClassOfTheFirstLaunchOnly)
{
    auto& lti = store().lti();
    const User teacher = addUser("teacher");
    const auto platform = addPlatform(moodle());
    const auto first = addClass(teacher, "A1"), second = addClass(teacher, "B2");
    EXPECT_FALSE(lti.classOfContext(platform, "course-17"));
    EXPECT_EQ(lti.linkContext(platform, "course-17", first), first);
    EXPECT_EQ(lti.linkContext(platform, "course-17", second), first) << "a second first launch finds the class";
    EXPECT_EQ(lti.classOfContext(platform, "course-17"), first);
    EXPECT_EQ(lti.linkContext(platform, "course-18", second), second);

    const auto other = addPlatform(moodle("tool-2"));
    EXPECT_FALSE(lti.classOfContext(other, "course-17")) << "course ids are per platform";

    std::set<std::int64_t> winners;
    std::mutex winnersLock;
    const std::int64_t classes[4] = {first, second, addClass(teacher, "C3"), addClass(teacher, "D4")};
    runAtOnce(4, [&](int thread) {
        const auto linked = lti.linkContext(platform, "raced", classes[thread]);
        std::lock_guard lock(winnersLock);
        winners.insert(linked);
    });
    EXPECT_EQ(winners.size(), 1U) << "every racer was told the same class";
}

TEST_P(LtiStoreConformance, AnAssignmentHasOneLineItemPerPlatform)
{
    auto& lti = store().lti();
    const User teacher = addUser("teacher");
    const auto assignment = addAssignment(addClass(teacher, "A1"));
    const auto platform = addPlatform(moodle());
    EXPECT_FALSE(lti.lineItemOf(platform, assignment));
    lti.setLineItem(platform, "https://moodle.example.edu/lineitems/1", assignment);
    lti.setLineItem(platform, "https://moodle.example.edu/lineitems/2", assignment);
    EXPECT_EQ(lti.lineItemOf(platform, assignment), "https://moodle.example.edu/lineitems/2");
    EXPECT_TRUE(store().labs().removeAssignment(assignment));
    EXPECT_FALSE(lti.lineItemOf(platform, assignment)) << "removed with the assignment";
}

TEST_P(LtiStoreConformance, AScoreIsLeasedDeliveredOnceAndANewerOneSupersedesAPendingOne)
{
    auto& lti = store().lti();
    const User teacher = addUser("teacher"), student = addUser("student");
    const auto assignment = addAssignment(addClass(teacher, "A1"));
    const auto platform = addPlatform(moodle());
    const auto first = lti.addScore(score(platform, student, assignment, 6));
    const auto second = lti.addScore(score(platform, student, assignment, 8.5));
    const auto teachers = lti.addScore(score(platform, teacher, assignment, 10));

    const auto now = 4000000000;   // later than any row's creation: all are due
    const auto claimed = lti.claimScores(now, 60, 10);
    ASSERT_EQ(claimed.size(), 2U) << "the superseded score is not sent";
    EXPECT_EQ(claimed[0].id, second);
    EXPECT_EQ(claimed[1].id, teachers);
    EXPECT_EQ(claimed[0].scoreGiven, 8.5);
    EXPECT_EQ(claimed[0].scoreMaximum, 10);
    EXPECT_EQ(claimed[0].userSubject, "moodle-user-" + std::to_string(student.id));
    EXPECT_EQ(claimed[0].userId, student.id);
    EXPECT_EQ(claimed[0].comment, "checks: 3 of 4");
    EXPECT_EQ(claimed[0].timestampMs, 1765000000123);
    EXPECT_EQ(claimed[0].attempts, 1);
    EXPECT_EQ(claimed[0].lease, 1);
    EXPECT_TRUE(lti.claimScores(now, 60, 10).empty()) << "leased";

    EXPECT_TRUE(lti.markDelivered(second, claimed[0].lease, now + 1));
    EXPECT_FALSE(lti.markDelivered(second, claimed[0].lease, now + 2)) << "once";
    const auto history = lti.scoresOf(assignment);
    ASSERT_EQ(history.size(), 3U);
    EXPECT_EQ(history[0].id, teachers) << "newest first";
    EXPECT_EQ(history[1].state, "delivered");
    EXPECT_EQ(history[1].deliveredAt, now + 1);
    EXPECT_EQ(history[2].id, first);
    EXPECT_EQ(history[2].state, "superseded");
    EXPECT_EQ(history[2].attempts, 0);
}

TEST_P(LtiStoreConformance, AFailedScoreWaitsForItsNextAttemptAndALeaseTakenOverFencesTheFirstNode)
{
    auto& lti = store().lti();
    const User teacher = addUser("teacher"), student = addUser("student");
    const auto assignment = addAssignment(addClass(teacher, "A1"));
    const auto platform = addPlatform(moodle());
    const auto id = lti.addScore(score(platform, student, assignment, 7));
    const std::int64_t now = 4000000000;

    auto claimed = lti.claimScores(now, 60, 10);
    ASSERT_EQ(claimed.size(), 1U);
    EXPECT_TRUE(lti.markFailed(id, claimed[0].lease, "platform answered 503", now + 30, false));
    EXPECT_TRUE(lti.claimScores(now + 29, 60, 10).empty()) << "not due before its next attempt";
    EXPECT_EQ(lti.scoresOf(assignment)[0].lastError, "platform answered 503");
    EXPECT_EQ(lti.scoresOf(assignment)[0].state, "pending");

    const auto slowNode = lti.claimScores(now + 30, 60, 10);   // leased until now + 90
    ASSERT_EQ(slowNode.size(), 1U);
    EXPECT_EQ(slowNode[0].attempts, 2);
    EXPECT_TRUE(lti.claimScores(now + 89, 60, 10).empty());
    const auto otherNode = lti.claimScores(now + 90, 60, 10);   // the lease ran out
    ASSERT_EQ(otherNode.size(), 1U);
    EXPECT_GT(otherNode[0].lease, slowNode[0].lease);
    EXPECT_FALSE(lti.markDelivered(id, slowNode[0].lease, now + 91)) << "fenced: its lease was taken over";
    EXPECT_FALSE(lti.markFailed(id, slowNode[0].lease, "late", now + 100, false));
    EXPECT_TRUE(lti.markFailed(id, otherNode[0].lease, "platform refused the token", now + 200, true));
    EXPECT_TRUE(lti.claimScores(now + 1000, 60, 10).empty()) << "given up";
    EXPECT_EQ(lti.scoresOf(assignment)[0].state, "failed");
    EXPECT_EQ(lti.scoresOf(assignment)[0].attempts, 3);
}

TEST_P(LtiStoreConformance, ClaimsRacingOnSeveralThreadsTakeEachScoreOnce)
{
    auto& lti = store().lti();
    const User teacher = addUser("teacher");
    const auto assignment = addAssignment(addClass(teacher, "A1"));
    const auto platform = addPlatform(moodle());
    std::vector<User> students;
    for (int i = 0; i < 40; ++i) {
        students.push_back(addUser("student" + std::to_string(i)));
        lti.addScore(score(platform, students.back(), assignment, i % 11));
    }
    std::vector<std::int64_t> taken;
    std::mutex takenLock;
    runAtOnce(4, [&](int) {
        for (;;) {
            const auto claimed = lti.claimScores(4000000000, 60, 3);
            if (claimed.empty()) return;
            std::lock_guard lock(takenLock);
            for (const auto& s : claimed) taken.push_back(s.id);
        }
    });
    std::sort(taken.begin(), taken.end());
    EXPECT_EQ(taken.size(), 40U);
    EXPECT_EQ(std::adjacent_find(taken.begin(), taken.end()), taken.end()) << "no score leased twice";
}

TEST_P(LtiStoreConformance, RemovingAPlatformRemovesItsCoursesLineItemsAndOutboxButKeepsTheClasses)
{
    auto& lti = store().lti();
    const User teacher = addUser("teacher"), student = addUser("student");
    const auto classId = addClass(teacher, "A1");
    const auto assignment = addAssignment(classId);
    const auto platform = addPlatform(moodle());
    lti.linkContext(platform, "course-17", classId);
    lti.setLineItem(platform, "https://moodle.example.edu/lineitems/1", assignment);
    lti.addScore(score(platform, student, assignment, 5));
    EXPECT_TRUE(lti.removePlatform(platform));
    EXPECT_FALSE(lti.removePlatform(platform));
    EXPECT_FALSE(lti.platform(platform));
    EXPECT_FALSE(lti.classOfContext(platform, "course-17"));
    EXPECT_FALSE(lti.lineItemOf(platform, assignment));
    EXPECT_TRUE(lti.scoresOf(assignment).empty());
    EXPECT_TRUE(store().labs().classInfo(classId)) << "the class and its work stay";
    const auto again = addPlatform(moodle());
    EXPECT_TRUE(lti.platform(again)->deploymentIds.size() == 2) << "registered again from scratch";
}

TEST_P(LtiStoreConformance, AScoreGoesToTheLineItemsOfThePlatformsThePersonIsLinkedTo)
{
    auto& lti = store().lti();
    const User teacher = addUser("teacher");
    const auto assignment = addAssignment(addClass(teacher, "A1"));
    const auto moodleId = addPlatform(moodle());
    LtiPlatform canvas = moodle("canvas-tool");
    canvas.issuer = "https://canvas.example.edu";
    const auto canvasId = addPlatform(canvas);
    const User ada = store().users().insertLinked("lti https://moodle.example.edu", "moodle-ada", "ada", kRoleUser);
    const User bob = addUser("bob");   // a local account, not linked to any platform
    EXPECT_TRUE(lti.scoreTargets(assignment, ada.id).empty()) << "no line item yet";

    lti.setLineItem(moodleId, "https://moodle.example.edu/lineitems/1", assignment);
    lti.setLineItem(canvasId, "https://canvas.example.edu/lineitems/9", assignment);
    const auto targets = lti.scoreTargets(assignment, ada.id);
    ASSERT_EQ(targets.size(), 1U) << "ada is linked to Moodle only";
    EXPECT_EQ(targets[0].platformId, moodleId);
    EXPECT_EQ(targets[0].lineItemUrl, "https://moodle.example.edu/lineitems/1");
    EXPECT_EQ(targets[0].userSubject, "moodle-ada");
    EXPECT_TRUE(lti.scoreTargets(assignment, bob.id).empty());
    EXPECT_TRUE(lti.scoreTargets(assignment + 1, ada.id).empty());
}

TEST_P(LtiStoreConformance, ADeepLinkRequestIsReadUntilTakenOnceAndPurgedWhenNeverAnswered)
{
    auto& lti = store().lti();
    const User teacher = addUser("teacher");
    const auto classId = addClass(teacher, "A1");
    const auto platform = addPlatform(moodle());
    const LtiDeepLinkRequest request{"key-1", platform, "1", "https://moodle.example.edu/return", "opaque", classId,
                                     teacher.id, 5000};
    lti.addDeepLink(request, 0);
    for (bool take : {false, false, true}) {
        const auto read = lti.deepLink("key-1", 4000, take);
        ASSERT_TRUE(read) << "take " << take;
        EXPECT_EQ(read->platformId, platform);
        EXPECT_EQ(read->deploymentId, "1");
        EXPECT_EQ(read->returnUrl, "https://moodle.example.edu/return");
        EXPECT_EQ(read->data, "opaque");
        EXPECT_EQ(read->classId, classId);
        EXPECT_EQ(read->userId, teacher.id);
        EXPECT_EQ(read->createdAt, 5000);
    }
    EXPECT_FALSE(lti.deepLink("key-1", 4000, false)) << "taken";
    EXPECT_FALSE(lti.deepLink("key-1", 4000, true)) << "once";

    lti.addDeepLink({"old", platform, "1", "https://r", "", classId, teacher.id, 5000}, 0);
    EXPECT_FALSE(lti.deepLink("old", 5001, false)) << "past its wait";
    lti.addDeepLink({"new", platform, "1", "https://r", "", classId, teacher.id, 9000}, 6000);
    EXPECT_FALSE(lti.deepLink("old", 0, false)) << "purged by the next request";
    EXPECT_TRUE(lti.deepLink("new", 0, false));
}

} // namespace
} // namespace tlmhub::test
