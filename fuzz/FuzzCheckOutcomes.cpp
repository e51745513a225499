// Fuzzes how a run is judged (issue 37): a check definition built from the input (each kind,
// measure and bound, through parseCheckDefinition as a teacher's would go) against a run and a
// reference made from the input too: any length, the column shorter than the time, times out
// of order or repeated, NaN and infinities. Judging must not crash or read out of bounds, a
// check awards its points or nothing, and what a student is shown of a hidden check is its
// name, pass or fail and points only.
#include "server/labs/LabChecks.h"

#include <fuzzer/FuzzedDataProvider.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <string>

namespace {

using namespace tlmhub;
using namespace tlmhub::server;

double sample(FuzzedDataProvider& in)
{
    switch (in.ConsumeIntegralInRange(0, 9)) {
    case 0: return std::numeric_limits<double>::quiet_NaN();
    case 1: return in.ConsumeBool() ? INFINITY : -INFINITY;
    case 2: return in.ConsumeFloatingPoint<double>();   // anything, up to the largest doubles
    default: return in.ConsumeFloatingPointInRange(-10.0, 10.0);
    }
}

// `n` samples of time, in order unless the input says otherwise, and a column of up to `n`.
ResultTable table(FuzzedDataProvider& in, const std::string& variable)
{
    ResultTable t;
    const std::size_t n = in.ConsumeIntegralInRange<std::size_t>(0, 300);
    const bool ordered = in.ConsumeBool();
    double now = 0;
    for (std::size_t i = 0; i < n; ++i) {
        now = ordered ? now + in.ConsumeFloatingPointInRange(0.0, 0.1) : sample(in);
        t.time.push_back(now);
    }
    ResultColumn column;
    column.name = in.ConsumeBool() ? variable : "Other#out#Value";
    const std::size_t m = in.ConsumeBool() ? n : in.ConsumeIntegralInRange<std::size_t>(0, n);
    for (std::size_t i = 0; i < m; ++i) column.data.push_back(sample(in));
    t.columns.push_back(std::move(column));
    return t;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    FuzzedDataProvider in(data, size);
    const std::string variable = "Mass#P1#x";
    nlohmann::json json = {{"variable", variable}};
    if (in.ConsumeBool()) {
        json["kind"] = "curve";
        if (in.ConsumeBool()) json["tolerance"] = sample(in);
    } else {
        static constexpr const char* kMeasures[] = {"final", "min", "max", "overshoot", "settling_time", "rise_time"};
        json["kind"] = "scalar";
        json["measure"] = kMeasures[in.ConsumeIntegralInRange(0, 5)];
        if (in.ConsumeBool()) json["min"] = sample(in);
        if (in.ConsumeBool()) json["max"] = sample(in);
        if (json["measure"] == "settling_time" && in.ConsumeBool()) json["band"] = sample(in);
    }
    std::string error;
    const auto definition = parseCheckDefinition(json, error);
    if (!definition) return 0;
    const double points = in.ConsumeFloatingPointInRange(0.0, 100.0);
    const bool pretest = in.ConsumeBool();
    const AssignmentCheck check{0, "hidden", pretest, points, checkDefinitionJson(*definition).dump()};
    const ResultTable run = table(in, variable);
    const ResultTable reference = table(in, variable);
    const auto outcomes = evaluateChecks({check}, run, in.ConsumeBool() ? &reference : nullptr, false);
    if (outcomes.size() != 1) std::abort();
    const CheckOutcome& o = outcomes[0];
    if (o.awarded != (o.passed ? o.points : 0.0)) std::abort();
    const nlohmann::json all = outcomesJson(outcomes);
    all.dump();
    const nlohmann::json shown = outcomesForStudent(all);
    for (const auto& [key, value] : shown.at(0).items()) {
        const bool always = key == "name" || key == "pretest" || key == "passed" || key == "points" || key == "awarded";
        if (!pretest && !always) std::abort();
    }
    return 0;
}
