#pragma once
// Extra component libraries: shared objects whose components register themselves with the
// ComponentFactory when loaded (their static TLMHUB_REGISTER_COMPONENT objects run at dlopen).
// Loading one runs its code with the host's rights, so only an administrator's start-up
// option may call this; nothing reachable from a model file or a request does.
#include "core/Status.h"

#include <string>
#include <vector>

namespace tlmhub {

// Loads the library at `path`; returns the type names it added (io_error if it cannot be
// loaded or adds none).
Result<std::vector<std::string>> loadComponentLibrary(const std::string& path);

} // namespace tlmhub
