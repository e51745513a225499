// Fuzzes the study request reader (parseStudyRequest) behind the server's JSON parser, and a
// plan of what it accepts: the first runs it hands out, completed with made-up objectives
// (an optimiser's batches), as a study's workers would.
#include "server/protocol/UntrustedJson.h"
#include "server/studies/StudyPlan.h"
#include "server/studies/StudyRequest.h"

#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    using namespace tlmhub::server;
    const UntrustedJson parsed = parseUntrustedJson(std::string(reinterpret_cast<const char*>(data), size));
    if (!parsed.ok()) return 0;
    StudyRequest request;
    std::string error;
    if (!parseStudyRequest(parsed.value, request, error)) return 0;
    request.parameterNames();
    request.outputs.columnNames();
    StudyPlan plan(request);
    // Bounded: a request may plan billions of runs.
    for (int i = 0; i < 64 && !plan.finished(); ++i) {
        const auto run = plan.next();
        if (!run) break;
        double objective = 0;
        for (double v : run->values) objective += v * v;
        plan.completed(run->index, i % 7 == 3 ? std::numeric_limits<double>::infinity() : objective);
    }
    return 0;
}
