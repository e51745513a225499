#include "server/store/ResultStore.h"

#include "server/store/ResultBlob.h"
#include "server/store/StoreError.h"

namespace tlmhub::server {

std::optional<ResultTable> ResultStore::result(std::int64_t jobId, const std::vector<std::string>& variables)
{
    const auto stored = blob(jobId);
    if (!stored) return std::nullopt;
    auto table = decodeResult(*stored, variables);
    if (!table) throw StoreError(StoreErrc::Corrupt, "the stored result of job " + std::to_string(jobId) +
                                                         " is not in a format this server reads");
    return table;
}

} // namespace tlmhub::server
