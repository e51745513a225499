// Issue 39 item 7: the teacher is warned when the template or the solution lies outside the
// parameter bounds they set or the solution fails its own checks (through a real server), and
// curve checks may measure their tolerance against the reference's largest magnitude
// ("scale": "range") while checks without the field are graded as before (no server needed).
#include "ServerHarness.h"
#include "TestFiles.h"

#include "server/labs/LabChecks.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tlmhub::test {
namespace {

namespace http = boost::beast::http;

// Position Servo's GainP.k is 0.0264249: inside [0, 0.1], outside [0, 0.01].
const nlohmann::json kGainWithinBounds = {{{"name", "GainP.k"}, {"min", 0}, {"max", 0.1}}};
const nlohmann::json kGainBelowTemplate = {{{"name", "GainP.k"}, {"min", 0}, {"max", 0.01}}};

std::vector<std::string> warningCodes(const nlohmann::json& assignment)
{
    std::vector<std::string> codes;
    for (const nlohmann::json& w : assignment.at("warnings")) codes.push_back(w.at("code").get<std::string>());
    return codes;
}

class AssignmentWarnings : public ::testing::Test {
protected:
    static void SetUpTestSuite()
    {
        server = new ServerProcess(freshTempDir("assignment-warnings"));
        createTestUsers(*server, {"stu"});
        HttpClient admin = loggedInAs(*server, "admin");
        const auto r = admin.post("/api/v1/users", {{"username", "tess"}, {"password", testPassword("tess")}, {"role", "teacher"}});
        ASSERT_EQ(r.status, 201) << r.body;
        HttpClient tess = loggedInAs(*server, "tess");
        servo = uploadModel(tess, kPositionServo, "servo");
        const auto created = tess.post("/api/v1/classes", {{"name", "Warnings"}});
        ASSERT_EQ(created.status, 201) << created.body;
        assignments = "/api/v1/classes/" + std::to_string(created.json()["id"].get<std::int64_t>()) + "/assignments";
        const auto joined = loggedInAs(*server, "stu").post("/api/v1/classes/join", {{"code", created.json()["join_code"]}});
        ASSERT_EQ(joined.status, 200) << joined.body;
    }
    static void TearDownTestSuite()
    {
        delete server;
        server = nullptr;
    }

    // tess's assignment on Position Servo (template and solution) where GainP.k may change within `bounds`.
    static nlohmann::json create(const nlohmann::json& bounds)
    {
        const auto r = loggedInAs(*server, "tess").post(assignments, {{"title", "Servo"}, {"template_model_id", servo},
                                                                     {"solution_model_id", servo},
                                                                     {"edit_mode", "parameters"}, {"parameters", bounds}});
        EXPECT_EQ(r.status, 201) << r.body;
        return r.json();
    }
    static std::string path(const nlohmann::json& assignment)
    {
        return "/api/v1/assignments/" + std::to_string(assignment["id"].get<std::int64_t>());
    }

    static inline ServerProcess* server = nullptr;
    static inline std::int64_t servo = 0;
    static inline std::string assignments;
};

TEST_F(AssignmentWarnings, AnOutOfBoundsTemplateIsWarnedOfToItsTeacherOnly)
{
    const nlohmann::json created = create(kGainBelowTemplate);
    EXPECT_EQ(warningCodes(created), (std::vector<std::string>{"template_outside_bounds", "solution_outside_bounds"}))
        << created.dump();
    const std::string message = created["warnings"][0]["message"].get<std::string>();
    EXPECT_NE(message.find("GainP.k"), std::string::npos) << message;
    EXPECT_NE(message.find("0.0264249"), std::string::npos) << message;
    EXPECT_NE(message.find("between 0 and 0.01"), std::string::npos) << message;

    HttpClient tess = loggedInAs(*server, "tess");
    EXPECT_EQ(warningCodes(tess.get(path(created)).json()), warningCodes(created));
    const auto seenByStudent = loggedInAs(*server, "stu").get(path(created));
    ASSERT_EQ(seenByStudent.status, 200) << seenByStudent.body;
    EXPECT_FALSE(seenByStudent.json().contains("warnings")) << seenByStudent.body;

    // Widened bounds: the update's reply has nothing left to warn of.
    const auto widened = tess.request(http::verb::patch, path(created),
                                      nlohmann::json{{"parameters", kGainWithinBounds}}.dump());
    ASSERT_EQ(widened.status, 200) << widened.body;
    EXPECT_TRUE(widened.json()["warnings"].empty()) << widened.body;
}

TEST_F(AssignmentWarnings, AGoodTemplateHasNoWarnings)
{
    const nlohmann::json created = create(kGainWithinBounds);
    ASSERT_TRUE(created.contains("warnings")) << created.dump();
    EXPECT_TRUE(created["warnings"].empty()) << created.dump();
    EXPECT_TRUE(loggedInAs(*server, "tess").get(path(created)).json()["warnings"].empty());
}

TEST_F(AssignmentWarnings, AListedParameterTheModelsLackIsWarnedOf)
{
    const nlohmann::json created = create({{{"name", "NoSuchComponent.k"}, {"max", 1}}});
    EXPECT_EQ(warningCodes(created), (std::vector<std::string>{"template_lacks_parameter", "solution_lacks_parameter"}))
        << created.dump();
}

TEST_F(AssignmentWarnings, ASolutionThatFailsItsOwnCheckIsWarnedOf)
{
    const nlohmann::json created = create(kGainWithinBounds);
    HttpClient tess = loggedInAs(*server, "tess");
    const auto checks = tess.request(
        http::verb::put, path(created) + "/checks",
        nlohmann::json{{"checks",
                        {{{"name", "Follows the reference"}, {"points", 1},
                          {"definition", {{"kind", "curve"}, {"variable", "Position_Sensor#out#Value"}, {"scale", "range"}}}},
                         {{"name", "Ends far away"}, {"points", 1},
                          {"definition", {{"kind", "scalar"}, {"variable", "Position_Sensor#out#Value"},
                                          {"measure", "final"}, {"min", 1000}}}}}}}
            .dump());
    ASSERT_EQ(checks.status, 200) << checks.body;
    // The range rule is stored as given.
    EXPECT_EQ(checks.json()["checks"][0]["definition"]["scale"], "range") << checks.body;
    const nlohmann::json seen = tess.get(path(created)).json();
    ASSERT_EQ(warningCodes(seen), std::vector<std::string>{"solution_fails_check"}) << seen.dump();
    EXPECT_NE(seen["warnings"][0]["message"].get<std::string>().find("Ends far away"), std::string::npos) << seen.dump();
}

// ---------------------------------------------------------------- the curve rules

using server::AssignmentCheck;
using server::CheckOutcome;

const std::string kWave = "Wave#out#Value";

// sin(2πt) over one period sampled every 1 ms, shifted by `offset`.
ResultTable sineRun(double offset)
{
    ResultTable table;
    auto& column = table.columns.emplace_back();
    column.name = kWave;
    for (int i = 0; i <= 1000; ++i) {
        const double t = i * 1e-3;
        table.time.push_back(t);
        column.data.push_back(std::sin(2 * std::numbers::pi * t) + offset);
    }
    return table;
}

CheckOutcome curveOutcome(const nlohmann::json& definition, const ResultTable& run, const ResultTable& reference)
{
    AssignmentCheck check;
    check.name = "wave";
    check.points = 1;
    check.definition = definition.dump();
    const auto outcomes = server::evaluateChecks({check}, run, &reference, false);
    EXPECT_EQ(outcomes.size(), 1u);
    return outcomes.at(0);
}

TEST(CurveCheckScale, TheRangeRulePassesANearZeroCurveThatTheSampleRuleFails)
{
    // 0.001 off a unit sine: 0.1 % of its largest magnitude, but far more than 1 % of each
    // sample near the zero crossings.
    const ResultTable reference = sineRun(0), run = sineRun(0.001);
    const nlohmann::json sample = {{"kind", "curve"}, {"variable", kWave}, {"tolerance", 0.01}};
    nlohmann::json range = sample;
    range["scale"] = "range";

    const CheckOutcome bySample = curveOutcome(sample, run, reference);
    EXPECT_FALSE(bySample.passed);
    const CheckOutcome byRange = curveOutcome(range, run, reference);
    EXPECT_TRUE(byRange.passed) << byRange.message;
    ASSERT_TRUE(byRange.deviation);
    EXPECT_NEAR(*byRange.deviation, 0.001, 1e-6);
    EXPECT_EQ(byRange.awarded, 1);

    // The range rule still fails a curve that is off by more than the tolerance of the range.
    const CheckOutcome farOff = curveOutcome(range, sineRun(0.02), reference);
    EXPECT_FALSE(farOff.passed);
    EXPECT_NE(farOff.message.find("largest magnitude"), std::string::npos) << farOff.message;
}

TEST(CurveCheckScale, ACheckWithoutScaleIsGradedAsBefore)
{
    const ResultTable reference = sineRun(0), run = sineRun(0.001);
    const nlohmann::json old = {{"kind", "curve"}, {"variable", kWave}, {"tolerance", 0.01}};
    const CheckOutcome outcome = curveOutcome(old, run, reference);
    // The .hvc rule by hand: the largest |1 - run/reference| among the samples it compares.
    double worst = 0, worstTime = 0;
    const auto& r = reference.columns[0].data;
    const auto& v = run.columns[0].data;
    for (std::size_t i = 0; i < r.size(); ++i) {
        if (std::fabs(v[i]) < 1e-100 || std::fabs(r[i]) < 1e-10) continue;
        if (const double d = std::fabs(1 - v[i] / r[i]); d > worst) {
            worst = d;
            worstTime = reference.time[i];
        }
    }
    EXPECT_FALSE(outcome.passed);
    EXPECT_EQ(outcome.awarded, 0);
    ASSERT_TRUE(outcome.deviation && outcome.worstTime);
    EXPECT_DOUBLE_EQ(*outcome.deviation, worst);
    EXPECT_DOUBLE_EQ(*outcome.worstTime, worstTime);
    EXPECT_EQ(outcome.message.find("largest magnitude"), std::string::npos) << outcome.message;
    // "scale": "sample" names the same rule; a stored definition without the field keeps none.
    nlohmann::json named = old;
    named["scale"] = "sample";
    const CheckOutcome namedOutcome = curveOutcome(named, run, reference);
    EXPECT_EQ(namedOutcome.passed, outcome.passed);
    EXPECT_EQ(namedOutcome.message, outcome.message);
    std::string error;
    const auto parsed = server::parseCheckDefinition(old, error);
    ASSERT_TRUE(parsed) << error;
    EXPECT_EQ(server::checkDefinitionJson(*parsed), old);
    EXPECT_FALSE(server::parseCheckDefinition({{"kind", "curve"}, {"variable", kWave}, {"scale", "local"}}, error));
    EXPECT_EQ(error, "definition.scale: must be sample or range");
}

} // namespace
} // namespace tlmhub::test
