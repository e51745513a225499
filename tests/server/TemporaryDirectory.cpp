#include "TemporaryDirectory.h"

#include <cstdlib>
#include <stdexcept>

namespace tlmhub::test {

std::filesystem::path makeTemporaryDirectory(const std::string& prefix)
{
    std::string pattern = (std::filesystem::temp_directory_path() / (prefix + "XXXXXX")).string();
    if (::mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("cannot make a directory " + pattern);
    return pattern;
}

} // namespace tlmhub::test
