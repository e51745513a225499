#pragma once
// Failures of the database itself, the same for every back end. What a caller can expect
// (no such row, a name already taken, a job no longer queued) comes back as a value from the
// store's methods; only the database failing (disk full, server gone, a statement the schema
// refuses) throws a StoreError, whose code is stable so the API maps it to one answer.
#include <stdexcept>
#include <string>

namespace tlmhub::server {

enum class StoreErrc {
    DiskFull,      // no room to write; deleting frees space (the API answers 507 storage_full)
    Unavailable,   // the database cannot be reached or opened (503)
    Busy,          // another writer held the database longer than the busy timeout (503)
    Constraint,    // the schema refused a write, e.g. a row that must exist is gone
    Corrupt,       // the file or a stored value is not what this version wrote
    Internal,      // anything else
};

// "disk_full", "unavailable", "busy", "constraint", "corrupt", "internal".
const char* storeErrcName(StoreErrc code);

class StoreError : public std::runtime_error {
public:
    StoreError(StoreErrc code, const std::string& message)
        : std::runtime_error(message), mCode(code)
    {
    }
    StoreErrc code() const { return mCode; }

private:
    StoreErrc mCode;
};

} // namespace tlmhub::server
