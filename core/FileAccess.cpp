#include "core/FileAccess.h"

#include <atomic>

namespace tlmhub {

namespace {
std::atomic<bool> gAllowed{true};
}

void setModelFileAccess(bool allowed) { gAllowed.store(allowed); }
bool modelFileAccessAllowed() { return gAllowed.load(); }

} // namespace tlmhub
