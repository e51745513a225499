// The parts of a study that need no server: reading a request, the measures of a run, the
// plan that hands out runs, and the hub that passes its events on.
#include "server/studies/RunMeasures.h"
#include "server/studies/StudyPlan.h"
#include "server/studies/StudyProgressHub.h"
#include "server/studies/StudyRequest.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <set>
#include <string>
#include <vector>

using namespace tlmhub::server;

namespace {

StudyRequest parsed(const nlohmann::json& body)
{
    StudyRequest request;
    std::string error;
    EXPECT_TRUE(parseStudyRequest(body, request, error)) << error;
    return request;
}

std::string refusal(const nlohmann::json& body)
{
    StudyRequest request;
    std::string error;
    EXPECT_FALSE(parseStudyRequest(body, request, error)) << body.dump();
    return error;
}

} // namespace

TEST(RunMeasures, StatisticsOfASeries)
{
    const std::vector<double> time = {0, 1, 2, 4};
    const std::vector<double> values = {0, 2, 2, 0};
    EXPECT_EQ(finalValue(values), 0);
    EXPECT_EQ(minValue(values), 0);
    EXPECT_EQ(maxValue(values), 2);
    // Trapezoids: 1 + 2 + 2 = 5 over 4 s.
    EXPECT_DOUBLE_EQ(timeAverage(time, values), 5.0 / 4.0);
    EXPECT_DOUBLE_EQ(timeAverage(std::vector<double>{3}, std::vector<double>{7}), 7);
    EXPECT_TRUE(std::isnan(finalValue({})));
}

TEST(RunMeasures, OvershootOfAStepResponse)
{
    // From 0 to 1 with a peak of 1.25: 25 %.
    EXPECT_DOUBLE_EQ(overshootPercent(std::vector<double>{0, 0.8, 1.25, 1.1, 1.0}), 25.0);
    // Falling from 2 to 1 through 0.5: 50 %.
    EXPECT_DOUBLE_EQ(overshootPercent(std::vector<double>{2, 1.2, 0.5, 1.0}), 50.0);
    EXPECT_EQ(overshootPercent(std::vector<double>{0, 0.5, 1.0}), 0.0);
    EXPECT_EQ(overshootPercent(std::vector<double>{1, 3, 1}), 0.0);   // no change: no overshoot
}

TEST(RunMeasures, IntegralOfSquaredErrorIsExactForLinearErrors)
{
    // e(t) = t on [0, 2] sampled finely: ∫ t² dt = 8/3; the trapezoidal rule's error is h²/6·2.
    std::vector<double> time, values, reference;
    for (int i = 0; i <= 2000; ++i) {
        time.push_back(i * 0.001);
        values.push_back(1 + i * 0.001);
        reference.push_back(1);
    }
    EXPECT_NEAR(integralSquaredError(time, values, reference), 8.0 / 3.0, 1e-6);
    const std::vector<std::pair<double, double>> curve = {{0, 0}, {1, 10}, {3, 30}};
    EXPECT_DOUBLE_EQ(interpolate(curve, 0.5), 5);
    EXPECT_DOUBLE_EQ(interpolate(curve, 2), 20);
    EXPECT_DOUBLE_EQ(interpolate(curve, -1), 0);
    EXPECT_DOUBLE_EQ(interpolate(curve, 9), 30);
}

TEST(StudyRequest, ReadsEachKind)
{
    const auto sweep = parsed({{"kind", "sweep"}, {"hmf", "<x/>"}, {"stop", 2}, {"parameters", {{"A.b", 3}}},
                               {"outputs", {{"variables", {"M#P#x"}}, {"values", {"final", "mean"}}}},
                               {"sweep", {{"parameters", {{"P.a", {1, 2, 3}}, {"P.b", {{"from", 0}, {"to", 1}, {"steps", 5}}}}}}}});
    EXPECT_EQ(sweep.plannedRuns(), 15u);
    EXPECT_EQ(sweep.parameterNames(), (std::vector<std::string>{"P.a", "P.b"}));
    EXPECT_EQ(sweep.outputs.columnNames(), (std::vector<std::string>{"M#P#x:final", "M#P#x:mean"}));
    EXPECT_EQ(sweep.fixedParameters.at("A.b"), "3");
    EXPECT_EQ(*sweep.settings.stop, 2);
    EXPECT_FALSE(sweep.objective);

    const auto random = parsed({{"kind", "sweep"}, {"model_id", 4},
                                {"sweep", {{"mode", "random"}, {"samples", 50}, {"seed", 9}, {"parameters", {{"P.a", {{"from", 0}, {"to", 1}}}}}}}});
    EXPECT_EQ(random.plannedRuns(), 50u);
    EXPECT_EQ(random.seed, 9u);

    const auto optimise = parsed({{"kind", "optimise"}, {"hmf", "<x/>"},
                                  {"optimise", {{"algorithm", "nelder-mead"}, {"max_evaluations", 80},
                                                {"parameters", {{"K.k", {{"min", 0}, {"max", 2}}}}},
                                                {"objective", {{"goal", "maximise"}, {"terms", {{{"function", "ise"}, {"variable", "a"}, {"reference_csv", "time,value\n0,1\n2,3\n"}}}}}}}}});
    EXPECT_EQ(optimise.plannedRuns(), 80u);
    ASSERT_TRUE(optimise.objective);
    EXPECT_TRUE(optimise.objective->maximise);
    EXPECT_EQ(optimise.objective->terms[0].referenceCurve.size(), 2u);
}

TEST(StudyRequest, RefusalsNameWhatIsWrong)
{
    EXPECT_NE(refusal({{"kind", "sweep"}}).find("model_id or hmf"), std::string::npos);
    EXPECT_NE(refusal({{"kind", "sweep"}, {"hmf", "x"}, {"sweep", {{"parameters", {{"P.a", "many"}}}}}}).find("P.a"), std::string::npos);
    EXPECT_NE(refusal({{"kind", "sweep"}, {"hmf", "x"}, {"sweep", {{"parameters", {{"P.a", {{"from", 0}, {"to", 1}, {"steps", 0}}}}}}}}).find("steps"),
              std::string::npos);
    EXPECT_NE(refusal({{"kind", "sweep"}, {"hmf", "x"}, {"sweep", {{"parameters", {{"P.a", {1}}}}}}, {"outputs", {{"values", {"median"}}}}}).find("median"),
              std::string::npos);
    EXPECT_NE(refusal({{"kind", "sensitivity"}, {"hmf", "x"}, {"outputs", {{"variables", {"v"}}}},
                       {"sensitivity", {{"runs", 10}, {"parameters", {{"P.a", {{"distribution", "normal"}, {"mean", 0}, {"sd", -1}}}}}}}}).find("sd"),
              std::string::npos);
    EXPECT_NE(refusal({{"kind", "optimise"}, {"hmf", "x"},
                       {"optimise", {{"parameters", {{"K.k", {{"min", 0}, {"max", 1}}}}},
                                     {"objective", {{"terms", {{{"function", "ise"}, {"variable", "a"}}}}}}}}}).find("reference"),
              std::string::npos);
    EXPECT_NE(refusal({{"kind", "optimise"}, {"hmf", "x"},
                       {"optimise", {{"parameters", {{"K.k", {{"min", 0}, {"max", 1}}}}},
                                     {"objective", {{"terms", {{{"function", "ise"}, {"variable", "a"}, {"reference_csv", "0,1\n0,2\n"}}}}}}}}}).find("increase"),
              std::string::npos);
    EXPECT_NE(refusal({{"kind", "sweep"}, {"hmf", "x"}, {"stop", "soon"}, {"sweep", {{"parameters", {{"P.a", {1}}}}}}}).find("stop"),
              std::string::npos);
}

// max_failed_fraction: a number from 0 to 1, 1 (never stop) when absent.
TEST(StudyRequest, MaxFailedFractionIsANumberFromZeroToOne)
{
    const nlohmann::json sweep = {{"kind", "sweep"}, {"hmf", "x"}, {"sweep", {{"parameters", {{"P.a", {1}}}}}}};
    EXPECT_EQ(parsed(sweep).maxFailedFraction, 1.0);
    for (const double fine : {0.0, 0.25, 1.0}) {
        nlohmann::json body = sweep;
        body["max_failed_fraction"] = fine;
        EXPECT_EQ(parsed(body).maxFailedFraction, fine);
    }
    for (const nlohmann::json& bad : {nlohmann::json(-0.01), nlohmann::json(1.01), nlohmann::json("0.5"), nlohmann::json(nullptr)}) {
        nlohmann::json body = sweep;
        body["max_failed_fraction"] = bad;
        EXPECT_NE(refusal(body).find("max_failed_fraction"), std::string::npos) << bad.dump();
    }
}

// A sweep hands out each set once, in index order; runs may come back in any order.
TEST(StudyPlan, HandsOutEverySweepSetOnce)
{
    const auto request = parsed({{"kind", "sweep"}, {"hmf", "x"},
                                 {"sweep", {{"parameters", {{"P.a", {1, 2}}, {"P.b", {10, 20, 30}}}}}}});
    StudyPlan plan(request);
    std::vector<PlannedRun> runs;
    while (auto run = plan.next()) runs.push_back(*run);
    ASSERT_EQ(runs.size(), 6u);
    EXPECT_EQ(runs[0].values, (std::vector<double>{1, 10}));
    EXPECT_EQ(runs[1].values, (std::vector<double>{1, 20}));
    EXPECT_EQ(runs[5].values, (std::vector<double>{2, 30}));
    EXPECT_FALSE(plan.finished());
    for (auto it = runs.rbegin(); it != runs.rend(); ++it) plan.completed(it->index, 0);
    EXPECT_TRUE(plan.finished());
}

// An optimisation's next batch comes only when the last one is complete, and the best point
// of a quadratic is found whatever order the batch's values come back in.
TEST(StudyPlan, OptimiserBatchesWaitForTheirLastRun)
{
    const auto request = parsed({{"kind", "optimise"}, {"hmf", "x"},
                                 {"optimise", {{"algorithm", "complex-rf"}, {"max_evaluations", 150}, {"seed", 3},
                                               {"parameters", {{"a", {{"min", -2}, {"max", 2}}}, {"b", {{"min", -2}, {"max", 2}}}}},
                                               {"objective", {{"terms", {{{"function", "final"}, {"variable", "v"}}}}}}}}});
    StudyPlan plan(request);
    auto f = [](const std::vector<double>& x) { return (x[0] - 0.5) * (x[0] - 0.5) + 3 * (x[1] + 0.25) * (x[1] + 0.25); };
    std::size_t evaluations = 0;
    while (!plan.finished()) {
        std::vector<PlannedRun> batch;
        while (auto run = plan.next()) batch.push_back(*run);
        ASSERT_FALSE(batch.empty());
        EXPECT_FALSE(plan.hasReady());
        // Completed last to first.
        for (auto it = batch.rbegin(); it != batch.rend(); ++it) plan.completed(it->index, f(it->values));
        evaluations += batch.size();
    }
    EXPECT_LE(evaluations, 150u);
    ASSERT_NE(plan.optimiser(), nullptr);
    EXPECT_LT(plan.optimiser()->bestValue(), 1e-3);
    EXPECT_NEAR(plan.optimiser()->best()[0], 0.5, 0.05);
    EXPECT_NEAR(plan.optimiser()->best()[1], -0.25, 0.05);
}

TEST(StudyProgressHub, ASubscriberThatComesAfterTheEndGetsTheLastEvent)
{
    StudyProgressHub hub;
    std::vector<nlohmann::json> seen;
    const std::uint64_t generation = hub.generation(7);
    hub.publish(7, generation, {{"state", "running"}});
    hub.finish(7, generation, {{"state", "done"}});
    EXPECT_EQ(hub.subscribe(7, [&](const nlohmann::json& e) { seen.push_back(e); }), 0u);
    ASSERT_EQ(seen.size(), 1u);
    EXPECT_EQ(seen[0]["state"], "done");
}

// A run stores its end before it publishes it, and a client that read `cancelled` may resume
// the study in between: the late end of the run before must not end the resumed one.
TEST(StudyProgressHub, TheLateEndOfTheRunBeforeAResumeEndsNeitherItNorItsSubscribers)
{
    StudyProgressHub hub;
    const std::uint64_t before = hub.generation(7);
    hub.reopen(7);   // the resume
    const std::uint64_t resumed = hub.generation(7);
    EXPECT_NE(resumed, before);

    std::vector<std::string> states;
    const auto sink = [&](const nlohmann::json& e) { states.push_back(e["state"].get<std::string>()); };
    EXPECT_NE(hub.subscribe(7, sink), 0u);
    hub.finish(7, before, {{"state", "cancelled"}});
    hub.publish(7, before, {{"state", "running"}});
    EXPECT_TRUE(states.empty());
    EXPECT_EQ(hub.subscriptionCount(), 1u);
    EXPECT_NE(hub.subscribe(7, sink), 0u) << "a subscriber after the late end follows the resumed run";

    hub.publish(7, resumed, {{"state", "running"}});
    hub.finish(7, resumed, {{"state", "done"}});
    EXPECT_EQ(states, (std::vector<std::string>{"running", "running", "done", "done"}));
    EXPECT_EQ(hub.subscriptionCount(), 0u);
}
