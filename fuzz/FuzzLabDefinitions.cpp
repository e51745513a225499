// Fuzzes what a teacher writes into an assignment behind the server's JSON parser: a check
// definition (parseCheckDefinition, then the check judged on a small made-up run) and the
// list of parameters a student may change (ParameterLock::parse, then a value asked of it).
#include "server/labs/LabChecks.h"
#include "server/labs/ParameterLock.h"
#include "server/protocol/UntrustedJson.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    using namespace tlmhub;
    using namespace tlmhub::server;
    const UntrustedJson parsed = parseUntrustedJson(std::string(reinterpret_cast<const char*>(data), size));
    if (!parsed.ok()) return 0;
    std::string error;
    if (const auto lock = ParameterLock::parse(parsed.value, error)) {
        lock->toJson();
        for (const AllowedParameter& p : lock->parameters()) lock->valueProblem(p.name, "0.5");
    }
    const auto definition = parseCheckDefinition(parsed.value, error);
    if (!definition) return 0;
    ResultTable run;
    for (int i = 0; i < 50; ++i) run.time.push_back(i * 0.01);
    ResultColumn column;
    column.name = definition->variable;
    for (int i = 0; i < 50; ++i) column.data.push_back(1 - std::exp(-i * 0.1));
    run.columns.push_back(column);
    const AssignmentCheck check{0, "fuzz", true, 1, checkDefinitionJson(*definition).dump()};
    outcomesJson(evaluateChecks({check}, run, &run, false));
    return 0;
}
