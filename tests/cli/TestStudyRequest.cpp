// The POST /studies bodies of `remote sweep` and `remote optimise`, and job parameters,
// as docs/studies.md defines them (no server needed).
#include "cli/remote/StudyRequest.h"

#include <gtest/gtest.h>

namespace tlmhub::cli::remote {
namespace {

Arguments sweepArguments(const std::vector<std::string>& args)
{
    return Arguments(args, {"mode", "csv"}, {"vary", "output"}, {"full"});
}

Arguments optimiseArguments(const std::vector<std::string>& args)
{
    return Arguments(args, {"algorithm", "max-evaluations", "seed", "csv"}, {"bound", "objective"}, {"maximise"});
}

TEST(RemoteStudyRequest, ARangeAndAListSweep)
{
    const nlohmann::json request = sweepRequest(
        "pump", sweepArguments({"m.hmf", "--vary", "Valve.Kv=1:5:10", "--vary", "Pump.Dp=1e-5,2e-5", "--output",
                                "Mass#P1#x:final,max", "--output", "Mass#P1#v:max,mean", "--full"}));
    EXPECT_EQ(request, nlohmann::json::parse(R"({
        "kind": "sweep", "name": "pump",
        "outputs": {"variables": ["Mass#P1#x", "Mass#P1#v"], "values": ["final", "max", "mean"], "full": true},
        "sweep": {"mode": "grid", "parameters": {"Valve.Kv": {"from": 1, "to": 5, "steps": 10},
                                                 "Pump.Dp": [1e-5, 2e-5]}}})"));
}

TEST(RemoteStudyRequest, ListModeAndNoOutputs)
{
    const nlohmann::json request =
        sweepRequest("m", sweepArguments({"m.hmf", "--vary=a=1,2", "--vary", "Sub$C.p=3,4", "--mode", "list"}));
    EXPECT_FALSE(request.contains("outputs"));
    EXPECT_EQ(request["sweep"],
              nlohmann::json::parse(R"({"mode": "list", "parameters": {"a": [1, 2], "Sub$C.p": [3, 4]}})"));
}

TEST(RemoteStudyRequest, BadSweepOptionsAreUsageErrors)
{
    for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
             {"m.hmf"},
             {"m.hmf", "--vary", "a"},
             {"m.hmf", "--vary", "a=1:2"},
             {"m.hmf", "--vary", "a=1:2:2.5"},
             {"m.hmf", "--vary", "a=1:2:0"},
             {"m.hmf", "--vary", "a=x,2"},
             {"m.hmf", "--vary", "a=1,2", "--vary", "a=3,4"},
             {"m.hmf", "--vary", "a=1,2", "--mode", "random"},
             {"m.hmf", "--vary", "a=1,2", "--output", "V"},
             {"m.hmf", "--vary", "a=1,2", "--output", "V:last"}})
        EXPECT_THROW(sweepRequest("m", sweepArguments(args)), UsageError) << args.back();
}

TEST(RemoteStudyRequest, OptimiseWithWeightedTerms)
{
    const nlohmann::json request = optimiseRequest(
        "servo", optimiseArguments({"m.hmf", "--bound", "Kp.k=0:0.01", "--bound", "Ki.k=0:0.1", "--objective",
                                    "ise:Mass#P1#x:Ref#out#y*0.5", "--objective", "overshoot:Mass#P1#x",
                                    "--objective", "final:Mass#P1#x*2", "--maximise", "--algorithm",
                                    "particle-swarm", "--max-evaluations", "200", "--seed", "1"}));
    EXPECT_EQ(request, nlohmann::json::parse(R"({
        "kind": "optimise", "name": "servo",
        "optimise": {
          "algorithm": "particle-swarm",
          "parameters": {"Kp.k": {"min": 0, "max": 0.01}, "Ki.k": {"min": 0, "max": 0.1}},
          "objective": {"goal": "maximise", "terms": [
            {"function": "ise", "variable": "Mass#P1#x", "reference_variable": "Ref#out#y", "weight": 0.5},
            {"function": "overshoot", "variable": "Mass#P1#x"},
            {"function": "final", "variable": "Mass#P1#x", "weight": 2}]},
          "max_evaluations": 200, "seed": 1}})"));
}

TEST(RemoteStudyRequest, OptimiseDefaults)
{
    const nlohmann::json request =
        optimiseRequest("m", optimiseArguments({"m.hmf", "--bound", "a=1:2", "--objective", "mean:V"}));
    EXPECT_EQ(request["optimise"]["algorithm"], "complex-rf");
    EXPECT_EQ(request["optimise"]["objective"]["goal"], "minimise");
    EXPECT_FALSE(request["optimise"].contains("max_evaluations"));
    EXPECT_FALSE(request["optimise"].contains("seed"));
}

TEST(RemoteStudyRequest, BadOptimiseOptionsAreUsageErrors)
{
    for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
             {"m.hmf", "--objective", "final:V"},
             {"m.hmf", "--bound", "a=1:2"},
             {"m.hmf", "--bound", "a=2:1", "--objective", "final:V"},
             {"m.hmf", "--bound", "a=1", "--objective", "final:V"},
             {"m.hmf", "--bound", "a=1:2", "--objective", "ise:V"},
             {"m.hmf", "--bound", "a=1:2", "--objective", "final:V:R"},
             {"m.hmf", "--bound", "a=1:2", "--objective", "median:V"},
             {"m.hmf", "--bound", "a=1:2", "--objective", "final:V*heavy"},
             {"m.hmf", "--bound", "a=1:2", "--objective", "final:V", "--max-evaluations", "0"},
             {"m.hmf", "--bound", "a=1:2", "--objective", "final:V", "--seed", "1.5"},
             {"m.hmf", "--bound", "a=1:2", "--objective", "final:V", "--algorithm", "magic"}})
        EXPECT_THROW(optimiseRequest("m", optimiseArguments(args)), UsageError) << args.back();
}

TEST(RemoteStudyRequest, ParametersAreNumbersWhenTheyAreNumbers)
{
    EXPECT_EQ(parameterValues({"Gain.k=0.5", "Step.t_step=2*t0", "relief_pressure=-1e7"}),
              nlohmann::json::parse(R"({"Gain.k": 0.5, "Step.t_step": "2*t0", "relief_pressure": -1e7})"));
    EXPECT_THROW(parameterValues({"Gain.k"}), UsageError);
    EXPECT_THROW(parameterValues({"=1"}), UsageError);
}

TEST(Arguments, FlagsNeverTakeTheNextArgument)
{
    const Arguments args({"--full", "m.hmf", "--csv=t.csv", "--vary", "-1,2"}, {"csv"}, {"vary"}, {"full"});
    EXPECT_EQ(args.positional(), std::vector<std::string>{"m.hmf"});
    EXPECT_TRUE(args.has("full"));
    EXPECT_EQ(args.value("csv"), "t.csv");
    EXPECT_EQ(args.values("vary"), std::vector<std::string>{"-1,2"});
    EXPECT_THROW(Arguments({"--csv", "a", "--csv", "b"}, {"csv"}, {}, {}), UsageError);
    EXPECT_THROW(Arguments({"--full=yes"}, {}, {}, {"full"}), UsageError);
    EXPECT_THROW(Arguments({"--unknown"}, {}, {}, {}), UsageError);
}

} // namespace
} // namespace tlmhub::cli::remote
