#include "server/store/StoreError.h"

namespace tlmhub::server {

const char* storeErrcName(StoreErrc code)
{
    switch (code) {
    case StoreErrc::DiskFull: return "disk_full";
    case StoreErrc::Unavailable: return "unavailable";
    case StoreErrc::Busy: return "busy";
    case StoreErrc::Constraint: return "constraint";
    case StoreErrc::Corrupt: return "corrupt";
    case StoreErrc::Internal: return "internal";
    }
    return "internal";
}

} // namespace tlmhub::server
