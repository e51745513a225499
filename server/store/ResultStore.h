#pragma once
// Stored job results (table job_results): one blob per finished job in ResultBlob's format,
// every column compressed on its own. Written by JobStore::finish, in the transaction that
// finishes the job; deleted with the job.
#include "core/ResultTable.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace tlmhub::server {

class ResultStore {
public:
    virtual ~ResultStore() = default;

    // The stored bytes of a job's result; nullopt when it has none.
    virtual std::optional<std::string> blob(std::int64_t jobId) = 0;
    virtual bool has(std::int64_t jobId) = 0;
    // Bytes of stored results of all of an owner's jobs and of the runs their studies keep
    // (the storage quota).
    virtual std::size_t storedBytes(std::int64_t ownerId) = 0;

    // The result with the columns `variables` names (empty: all); only those are
    // decompressed. nullopt when the job has no result.
    std::optional<ResultTable> result(std::int64_t jobId, const std::vector<std::string>& variables = {});
};

} // namespace tlmhub::server
