// The automatic checks of a lab assignment and the gradebook export, without a server: runs
// are built as result tables from analytic step responses, so the expected measures are known.
#include "server/labs/Gradebook.h"
#include "server/labs/LabChecks.h"
#include "core/Validation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>

using namespace tlmhub::server;
using tlmhub::ResultTable;

namespace {

const std::string kVariable = "Mass#P1#x";

// A table of one variable sampled at start, start + step, ... up to stop.
ResultTable sampled(double start, double stop, double step, const std::function<double(double)>& f,
                    const std::string& name = kVariable)
{
    ResultTable table;
    auto& column = table.columns.emplace_back();
    column.name = name;
    const auto n = static_cast<std::size_t>(std::llround((stop - start) / step));
    for (std::size_t i = 0; i <= n; ++i) {
        const double t = start + static_cast<double>(i) * step;
        table.time.push_back(t);
        column.data.push_back(f(t));
    }
    return table;
}

AssignmentCheck check(const std::string& name, const nlohmann::json& definition, double points = 1,
                      bool pretest = false)
{
    AssignmentCheck c;
    c.name = name;
    c.points = points;
    c.pretest = pretest;
    c.definition = definition.dump();
    return c;
}

CheckOutcome judged(const nlohmann::json& definition, const ResultTable& run, const ResultTable* reference = nullptr)
{
    const auto outcomes = evaluateChecks({check("check", definition)}, run, reference, false);
    EXPECT_EQ(outcomes.size(), 1u);
    return outcomes.at(0);
}

std::string refusal(const nlohmann::json& definition)
{
    std::string error;
    EXPECT_FALSE(parseCheckDefinition(definition, error)) << definition.dump();
    return error;
}

constexpr double kTau = 0.5;
constexpr double kStep = 0.01;

double firstOrder(double t) { return 1.0 - std::exp(-t / kTau); }

} // namespace

TEST(LabChecks, SettlingAndRiseTimeOfAFirstOrderStep)
{
    // Long enough (20 τ) that the final value is 1 to 2e-9.
    const ResultTable run = sampled(0, 20 * kTau, kStep, firstOrder);
    const auto& values = run.columns[0].data;
    // Crossings are interpolated linearly between samples; for this curve that errs by at most
    // h²/(8τ) per crossing, so h²/τ holds with room while one whole step (h) does not.
    const double tolerance = kStep * kStep / kTau;
    // Within ±2 % of the change: e^(-t/τ) = 0.02.
    EXPECT_NEAR(settlingTime(run.time, values, 0.02), kTau * std::log(50.0), tolerance);
    EXPECT_NEAR(settlingTime(run.time, values, 0.05), kTau * std::log(20.0), tolerance);
    // 10 % at τ·ln(10/9), 90 % at τ·ln(10).
    const auto rise = riseTime(run.time, values);
    ASSERT_TRUE(rise);
    EXPECT_NEAR(*rise, kTau * std::log(9.0), tolerance);

    // A falling step has the same times.
    std::vector<double> falling(values.size());
    for (std::size_t i = 0; i < values.size(); ++i) falling[i] = 3.0 - 2.0 * values[i];
    EXPECT_NEAR(settlingTime(run.time, falling, 0.02), kTau * std::log(50.0), tolerance);
    EXPECT_NEAR(*riseTime(run.time, falling), kTau * std::log(9.0), tolerance);
}

TEST(LabChecks, SettlingAndRiseTimeOfFlatOrShortSeries)
{
    const std::vector<double> time = {0, 1, 2};
    EXPECT_EQ(settlingTime(time, std::vector<double>{1, 1, 1}, 0.02), 0.0);
    EXPECT_FALSE(riseTime(time, std::vector<double>{1, 1, 1}));
    EXPECT_FALSE(riseTime(time, std::vector<double>{1, 5, 1}));   // returns to where it began
    // Outside the band until the last sample: the crossing is on the last interval.
    EXPECT_DOUBLE_EQ(settlingTime(time, std::vector<double>{0, 0, 1}, 0.5), 1.5);
    // Measured from the first sample.
    EXPECT_DOUBLE_EQ(settlingTime(std::vector<double>{10, 11, 12}, std::vector<double>{0, 0, 1}, 0.5), 1.5);
}

TEST(LabChecks, ScalarChecksOfAFirstOrderStep)
{
    const ResultTable run = sampled(0, 20 * kTau, kStep, firstOrder);
    const double settling = kTau * std::log(50.0);

    auto outcome = judged({{"kind", "scalar"}, {"variable", kVariable}, {"measure", "settling_time"},
                           {"min", settling - 0.01}, {"max", settling + 0.01}},
                          run);
    EXPECT_TRUE(outcome.passed) << outcome.message;
    ASSERT_TRUE(outcome.value);
    EXPECT_NEAR(*outcome.value, settling, 1e-3);
    EXPECT_EQ(outcome.message, "");
    EXPECT_FALSE(outcome.deviation);

    outcome = judged({{"kind", "scalar"}, {"variable", kVariable}, {"measure", "rise_time"}, {"max", 1}}, run);
    EXPECT_FALSE(outcome.passed);
    // τ·ln 9 = 1.09861; the digits after 1.098 depend on the sampling.
    EXPECT_TRUE(outcome.message.starts_with("the rise_time of Mass#P1#x is 1.098")) << outcome.message;
    EXPECT_TRUE(outcome.message.ends_with(" s, required at most 1 s")) << outcome.message;

    outcome = judged({{"kind", "scalar"}, {"variable", kVariable}, {"measure", "final"}, {"min", 1.0}}, run);
    EXPECT_FALSE(outcome.passed);   // 1 - e^-20 is just below 1
    outcome = judged({{"kind", "scalar"}, {"variable", kVariable}, {"measure", "min"}, {"min", 0}, {"max", 0}}, run);
    EXPECT_TRUE(outcome.passed) << outcome.message;   // inclusive bounds
    outcome = judged({{"kind", "scalar"}, {"variable", kVariable}, {"measure", "max"}, {"min", 1.5}}, run);
    EXPECT_FALSE(outcome.passed);
    EXPECT_EQ(outcome.message, "the max of Mass#P1#x is 1, required at least 1.5");
}

TEST(LabChecks, OvershootOfAnUnderdampedSecondOrderStep)
{
    const double zeta = 0.3, omega = 2.0, step = 0.001;
    const double damped = omega * std::sqrt(1 - zeta * zeta);
    const auto response = [&](double t) {
        return 1.0 - std::exp(-zeta * omega * t) *
                         (std::cos(damped * t) + zeta / std::sqrt(1 - zeta * zeta) * std::sin(damped * t));
    };
    // 30 s: the oscillation has decayed to e^-18, so the final value is 1.
    const ResultTable run = sampled(0, 30, step, response);
    const double expected = 100.0 * std::exp(-zeta * std::numbers::pi / std::sqrt(1 - zeta * zeta));
    // The peak falls between samples: it is missed by at most ½·|y''|·(h/2)² ≈ 7e-7, i.e. 7e-5 %.
    const double tolerance = 1e-3;

    auto outcome = judged({{"kind", "scalar"}, {"variable", kVariable}, {"measure", "overshoot"}, {"max", 40}}, run);
    EXPECT_TRUE(outcome.passed) << outcome.message;
    ASSERT_TRUE(outcome.value);
    EXPECT_NEAR(*outcome.value, expected, tolerance);

    outcome = judged({{"kind", "scalar"}, {"variable", kVariable}, {"measure", "overshoot"}, {"min", 0}, {"max", 30}},
                     run);
    EXPECT_FALSE(outcome.passed);
    EXPECT_TRUE(outcome.message.starts_with("the overshoot of Mass#P1#x is 37.23")) << outcome.message;
    EXPECT_TRUE(outcome.message.ends_with(" %, required between 0 and 30 %")) << outcome.message;
}

TEST(LabChecks, CurveWithinToleranceOfTheReferencePasses)
{
    const auto reference = sampled(0, 3, 0.01, [](double t) { return 1.0 + t; });
    const auto run = sampled(0, 3, 0.01, [](double t) { return (1.0 + t) * (1.0 + 0.005 * std::sin(5 * t)); });
    const auto outcome =
        judged({{"kind", "curve"}, {"variable", kVariable}, {"tolerance", 0.01}}, run, &reference);
    EXPECT_TRUE(outcome.passed) << outcome.message;
    EXPECT_EQ(outcome.message, "");
    ASSERT_TRUE(outcome.deviation);
    EXPECT_LE(*outcome.deviation, 0.005 + 1e-12);
    EXPECT_GT(*outcome.deviation, 0.004);
    EXPECT_FALSE(outcome.value);
}

TEST(LabChecks, CurveScaledBeyondToleranceFails)
{
    const auto reference = sampled(0, 3, 0.01, [](double t) { return 1.0 + t; });
    const nlohmann::json definition = {{"kind", "curve"}, {"variable", kVariable}, {"tolerance", 0.05}};

    const auto scaled = sampled(0, 3, 0.01, [](double t) { return 1.1 * (1.0 + t); });
    auto outcome = judged(definition, scaled, &reference);
    EXPECT_FALSE(outcome.passed);
    ASSERT_TRUE(outcome.deviation);
    EXPECT_NEAR(*outcome.deviation, 0.1, 1e-12);

    // 10 % off at t = 1.2 only, less on either side: that is the worst sample.
    const auto bump = sampled(0, 3, 0.01, [](double t) {
        return (1.0 + t) * (1.0 + 0.1 * std::exp(-(t - 1.2) * (t - 1.2) / 0.09));
    });
    outcome = judged(definition, bump, &reference);
    EXPECT_FALSE(outcome.passed);
    ASSERT_TRUE(outcome.deviation && outcome.worstTime);
    EXPECT_NEAR(*outcome.deviation, 0.1, 1e-12);
    EXPECT_NEAR(*outcome.worstTime, 1.2, 1e-9);
    EXPECT_EQ(outcome.message, "Mass#P1#x differs by 10 % at t = 1.2 s (tolerance 5 %)");
    EXPECT_EQ(outcome.awarded, 0);
}

TEST(LabChecks, CurveReferenceIsInterpolatedAtTheRunsTimes)
{
    // The reference has a tenth of the run's samples; a straight line interpolates exactly,
    // where taking the nearest reference sample would be off by up to 7 %.
    const auto line = [](double t) { return 2.0 + 3.0 * t; };
    const auto reference = sampled(0, 2, 0.1, line);
    const auto run = sampled(0, 2, 0.01, line);
    const auto outcome = judged({{"kind", "curve"}, {"variable", kVariable}, {"tolerance", 1e-9}}, run, &reference);
    EXPECT_TRUE(outcome.passed) << outcome.message;
    ASSERT_TRUE(outcome.deviation);
    EXPECT_LT(*outcome.deviation, 1e-12);

    // Beyond the reference's last time its last value holds.
    const auto longer = sampled(0, 3, 0.01, [&](double t) { return line(std::min(t, 2.0)); });
    EXPECT_TRUE(judged({{"kind", "curve"}, {"variable", kVariable}, {"tolerance", 1e-9}}, longer, &reference).passed);
}

TEST(LabChecks, CurveSkipsTinyReferenceValuesAndFailsOnNaN)
{
    // A reference of zeros is never compared (core.md §7.4), so any run passes and there is
    // no deviation to report.
    const auto zeros = sampled(0, 1, 0.1, [](double) { return 0.0; });
    const auto ones = sampled(0, 1, 0.1, [](double) { return 1.0; });
    const nlohmann::json definition = {{"kind", "curve"}, {"variable", kVariable}};
    auto outcome = judged(definition, ones, &zeros);
    EXPECT_TRUE(outcome.passed);
    EXPECT_FALSE(outcome.deviation);

    auto broken = ones;
    broken.columns[0].data[4] = std::nan("");
    outcome = judged(definition, broken, &ones);
    EXPECT_FALSE(outcome.passed);
    EXPECT_EQ(outcome.message, "'Mass#P1#x' is not a finite number at t = 0.4 s");
}

// Found by fuzz/check-outcomes under ASan: a run time that is NaN, against a reference of one
// sample, sent the interpolation past that sample.
TEST(LabChecks, CurveAgainstADamagedTableFailsOrPassesWithoutReadingPastIt)
{
    const nlohmann::json definition = {{"kind", "curve"}, {"variable", kVariable}};
    const auto ones = sampled(0, 1, 0.1, [](double) { return 1.0; });
    auto shuffled = ones;
    std::swap(shuffled.time[2], shuffled.time[8]);   // the same values at times out of order
    auto outcome = judged(definition, ones, &shuffled);
    EXPECT_TRUE(outcome.passed) << outcome.message;   // every reference value is 1

    auto nanTime = ones;
    nanTime.time[3] = std::nan("");
    const auto oneSample = sampled(0, 0, 0.1, [](double) { return 1.0; });
    outcome = judged(definition, nanTime, &oneSample);
    EXPECT_FALSE(outcome.passed);
    EXPECT_EQ(outcome.message, "the run's time is not a finite number at sample 4");
    EXPECT_EQ(tlmhub::interpolateReference({1.0}, {5.0}, std::nan("")), 5.0);
    EXPECT_TRUE(std::isnan(tlmhub::interpolateReference({0.0, 1.0, 2.0}, {5.0, 6.0, 7.0}, std::nan(""))));
}

TEST(LabChecks, MissingVariablesFailWithTheirName)
{
    const auto run = sampled(0, 1, 0.1, firstOrder);
    const auto other = sampled(0, 1, 0.1, firstOrder, "Other#y");
    const nlohmann::json curve = {{"kind", "curve"}, {"variable", kVariable}};

    auto outcome = judged(curve, other, &run);
    EXPECT_FALSE(outcome.passed);
    EXPECT_EQ(outcome.message, "the run has no variable 'Mass#P1#x'");
    outcome = judged(curve, run, &other);
    EXPECT_FALSE(outcome.passed);
    EXPECT_EQ(outcome.message, "the reference run has no variable 'Mass#P1#x'");
    outcome = judged(curve, run, nullptr);
    EXPECT_FALSE(outcome.passed);
    EXPECT_EQ(outcome.message, "there is no reference run to compare 'Mass#P1#x' with");
    outcome = judged({{"kind", "scalar"}, {"variable", kVariable}, {"measure", "final"}, {"max", 1}}, other);
    EXPECT_FALSE(outcome.passed);
    EXPECT_EQ(outcome.message, "the run has no variable 'Mass#P1#x'");
    outcome = judged({{"kind", "scalar"}, {"variable", "Other#y"}, {"measure", "rise_time"}, {"max", 1}},
                     sampled(0, 1, 0.1, [](double) { return 4.0; }, "Other#y"));
    EXPECT_FALSE(outcome.passed);
    EXPECT_EQ(outcome.message, "'Other#y' does not change, so it has no rise time");
}

TEST(LabChecks, UnreadableStoredDefinitionFailsWithoutThrowing)
{
    AssignmentCheck broken;
    broken.name = "broken";
    broken.points = 3;
    broken.definition = "{not json";
    const auto outcomes = evaluateChecks({broken}, sampled(0, 1, 0.1, firstOrder), nullptr, false);
    ASSERT_EQ(outcomes.size(), 1u);
    EXPECT_FALSE(outcomes[0].passed);
    EXPECT_EQ(outcomes[0].awarded, 0);
    EXPECT_EQ(outcomes[0].message, "the check cannot be read: definition is not JSON");
}

TEST(LabChecks, PretestsOnlyAndPointsAwarded)
{
    const auto run = sampled(0, 20 * kTau, kStep, firstOrder);
    const std::vector<AssignmentCheck> checks = {
        check("follows", {{"kind", "curve"}, {"variable", kVariable}}, 2, true),
        check("overshoot", {{"kind", "scalar"}, {"variable", kVariable}, {"measure", "overshoot"}, {"max", 5}}, 1.5),
        check("fast", {{"kind", "scalar"}, {"variable", kVariable}, {"measure", "rise_time"}, {"max", 0.5}}, 4),
    };

    const auto pretests = evaluateChecks(checks, run, &run, true);
    ASSERT_EQ(pretests.size(), 1u);
    EXPECT_EQ(pretests[0].name, "follows");
    EXPECT_TRUE(pretests[0].pretest);
    EXPECT_TRUE(pretests[0].passed) << pretests[0].message;
    EXPECT_EQ(pretests[0].awarded, 2);

    const auto all = evaluateChecks(checks, run, &run, false);
    ASSERT_EQ(all.size(), 3u);
    EXPECT_EQ(all[1].name, "overshoot");
    EXPECT_TRUE(all[1].passed) << all[1].message;
    EXPECT_EQ(all[1].points, 1.5);
    EXPECT_EQ(all[1].awarded, 1.5);
    EXPECT_EQ(all[2].name, "fast");
    EXPECT_FALSE(all[2].passed);
    EXPECT_EQ(all[2].points, 4);
    EXPECT_EQ(all[2].awarded, 0);

    const auto json = outcomesJson(all);
    ASSERT_EQ(json.size(), 3u);
    EXPECT_EQ(json[0], (nlohmann::json{{"name", "follows"}, {"pretest", true}, {"passed", true}, {"points", 2.0},
                                       {"awarded", 2.0}, {"deviation", 0.0}, {"worst_time", 0.01}, {"message", ""}}));
    EXPECT_EQ(json[1], (nlohmann::json{{"name", "overshoot"}, {"pretest", false}, {"passed", true}, {"points", 1.5},
                                       {"awarded", 1.5}, {"value", 0.0}, {"message", ""}}));
    EXPECT_FALSE(json[2]["passed"].get<bool>());
    EXPECT_EQ(json[2]["awarded"].get<double>(), 0);
    EXPECT_NE(json[2]["message"].get<std::string>(), "");
}

TEST(LabChecks, DefinitionDefaultsAndRoundTrip)
{
    std::string error;
    const auto curve = parseCheckDefinition({{"kind", "curve"}, {"variable", kVariable}}, error);
    ASSERT_TRUE(curve) << error;
    EXPECT_EQ(curve->tolerance, 0.01);
    const auto settling = parseCheckDefinition(
        {{"kind", "scalar"}, {"variable", kVariable}, {"measure", "settling_time"}, {"max", 2}}, error);
    ASSERT_TRUE(settling) << error;
    EXPECT_EQ(settling->band, 0.02);
    EXPECT_FALSE(settling->min);
    EXPECT_EQ(settling->max, 2.0);

    for (const nlohmann::json& json :
         {nlohmann::json{{"kind", "curve"}, {"variable", kVariable}, {"tolerance", 0.05}},
          nlohmann::json{{"kind", "scalar"}, {"variable", kVariable}, {"measure", "overshoot"}, {"min", 1}, {"max", 10}},
          nlohmann::json{{"kind", "scalar"}, {"variable", kVariable}, {"measure", "settling_time"}, {"min", 1},
                         {"band", 0.05}}}) {
        const auto definition = parseCheckDefinition(json, error);
        ASSERT_TRUE(definition) << error;
        EXPECT_EQ(checkDefinitionJson(*definition), json);
    }
}

TEST(LabChecks, DefinitionRejectionsNameTheField)
{
    const nlohmann::json curve = {{"kind", "curve"}, {"variable", kVariable}};
    const nlohmann::json scalar = {{"kind", "scalar"}, {"variable", kVariable}, {"measure", "final"}, {"max", 1}};
    const auto with = [](nlohmann::json json, const std::string& key, const nlohmann::json& value) {
        json[key] = value;
        return json;
    };
    const auto without = [](nlohmann::json json, const std::string& key) {
        json.erase(key);
        return json;
    };

    EXPECT_EQ(refusal(nlohmann::json::array()), "definition: must be an object");
    EXPECT_EQ(refusal(without(curve, "kind")), "definition.kind: must be curve or scalar");
    EXPECT_EQ(refusal(with(curve, "kind", "step")), "definition.kind: must be curve or scalar");
    EXPECT_EQ(refusal(without(curve, "variable")), "definition.variable: must be a non-empty string");
    EXPECT_EQ(refusal(with(curve, "variable", "")), "definition.variable: must be a non-empty string");
    EXPECT_EQ(refusal(with(scalar, "variable", 3)), "definition.variable: must be a non-empty string");
    EXPECT_EQ(refusal(with(curve, "tolerance", 0)), "definition.tolerance: must be greater than 0");
    EXPECT_EQ(refusal(with(curve, "tolerance", -0.1)), "definition.tolerance: must be greater than 0");
    EXPECT_EQ(refusal(with(curve, "tolerance", "5 %")), "definition.tolerance: must be a number");
    EXPECT_EQ(refusal(with(curve, "measure", "final")), "definition.measure: unknown field for a curve check");
    EXPECT_EQ(refusal(with(curve, "colour", "red")), "definition.colour: unknown field for a curve check");
    EXPECT_EQ(refusal(with(scalar, "tolerance", 0.1)), "definition.tolerance: unknown field for a scalar check");
    EXPECT_EQ(refusal(with(scalar, "measure", "median")),
              "definition.measure: must be one of final, min, max, overshoot, settling_time, rise_time");
    EXPECT_EQ(refusal(without(scalar, "measure")),
              "definition.measure: must be one of final, min, max, overshoot, settling_time, rise_time");
    EXPECT_EQ(refusal(without(scalar, "max")), "definition.min: a scalar check needs min, max or both");
    EXPECT_EQ(refusal(with(scalar, "min", "0")), "definition.min: must be a number");
    EXPECT_EQ(refusal(with(scalar, "max", nullptr)), "definition.max: must be a number");
    EXPECT_EQ(refusal(with(scalar, "min", 2)), "definition.max: must not be less than min");
    EXPECT_EQ(refusal(with(scalar, "band", 0.1)), "definition.band: only for the measure settling_time");

    const auto settling = with(scalar, "measure", "settling_time");
    std::string error;
    EXPECT_TRUE(parseCheckDefinition(with(settling, "band", 0.1), error)) << error;
    for (double band : {0.0, 1.0, 1.5, -0.1})
        EXPECT_EQ(refusal(with(settling, "band", band)), "definition.band: must be greater than 0 and less than 1");
    EXPECT_EQ(refusal(with(settling, "band", "2 %")), "definition.band: must be a number");
}

TEST(Gradebook, CellsAreNeutralisedAndQuoted)
{
    EXPECT_EQ(spreadsheetSafeCell("alice"), "alice");
    EXPECT_EQ(spreadsheetSafeCell(""), "");
    EXPECT_EQ(spreadsheetSafeCell("=1+2"), "'=1+2");
    EXPECT_EQ(spreadsheetSafeCell("+x"), "'+x");
    EXPECT_EQ(spreadsheetSafeCell("-3"), "'-3");
    EXPECT_EQ(spreadsheetSafeCell("@SUM(A1)"), "'@SUM(A1)");
    EXPECT_EQ(spreadsheetSafeCell("\tx"), "'\tx");
    EXPECT_EQ(spreadsheetSafeCell("\r=1"), "\"'\r'=1\"");
    EXPECT_EQ(spreadsheetSafeCell("a,b"), "\"a,b\"");
    EXPECT_EQ(spreadsheetSafeCell("say \"hi\""), "\"say \"\"hi\"\"\"");
    EXPECT_EQ(spreadsheetSafeCell("two\nlines"), "\"two\nlines\"");
    EXPECT_EQ(spreadsheetSafeCell("=HYPERLINK(\"x\",1)"), "\"'=HYPERLINK(\"\"x\"\",1)\"");
    EXPECT_EQ(spreadsheetSafeCell("a=1"), "a=1");   // only a sign that starts a field starts a formula
    // Issue 37 L4: an import splitting on ';', tabs or bars, or ignoring the quotes, finds a
    // field after each of them.
    EXPECT_EQ(spreadsheetSafeCell("x;=1+2"), "x;'=1+2");
    EXPECT_EQ(spreadsheetSafeCell("x\t-1"), "x\t'-1");
    EXPECT_EQ(spreadsheetSafeCell("x| @SUM(A1)"), "x| '@SUM(A1)");
    EXPECT_EQ(spreadsheetSafeCell("x,=1"), "\"x,'=1\"");
    EXPECT_EQ(spreadsheetSafeCell("two\n+lines"), "\"two\n'+lines\"");
    EXPECT_EQ(spreadsheetSafeCell("x; y=1"), "x; y=1");
}

TEST(Gradebook, WholeCsv)
{
    const std::vector<std::string> titles = {"Servo", "=Step, part 2"};
    const std::vector<GradebookRow> rows = {
        {"alice", {{2.5, false}, {std::nullopt, false}}},
        {"-bob", {{1, true}, {0.1234567, false}}},
        {"carol", {{std::nullopt, false}, {std::nullopt, false}}},
    };
    EXPECT_EQ(gradebookCsv(titles, rows),
              "student,Servo,Servo late,\"'=Step, part 2\",\"'=Step, part 2 late\",total\n"
              "alice,2.5,,,,2.5\n"
              "'-bob,1,late,0.123457,,1.12346\n"
              "carol,,,,,0\n");
    EXPECT_EQ(gradebookCsv({}, {}), "student,total\n");
}
