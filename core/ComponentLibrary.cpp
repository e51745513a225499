#include "core/ComponentLibrary.h"

#include "core/ComponentFactory.h"

#include <dlfcn.h>

#include <algorithm>

namespace tlmhub {

Result<std::vector<std::string>> loadComponentLibrary(const std::string& path)
{
    const std::vector<std::string> before = ComponentFactory::instance().typeNames();
    // RTLD_NOW: a library with unresolved symbols fails here, not in the middle of a run.
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_GLOBAL);
    if (!handle) {
        const char* reason = dlerror();
        return Status{StatusCode::IoError,
                      "cannot load component library '" + path + "': " + (reason ? reason : "unknown")};
    }
    // The handle is kept open for the life of the process: its components may be in use.
    const std::vector<std::string> after = ComponentFactory::instance().typeNames();
    std::vector<std::string> addedTypes;
    std::set_difference(after.begin(), after.end(), before.begin(), before.end(),
                        std::back_inserter(addedTypes));
    if (addedTypes.empty())
        return Status{StatusCode::IoError, "component library '" + path + "' registered no component types"};
    return addedTypes;
}

} // namespace tlmhub
