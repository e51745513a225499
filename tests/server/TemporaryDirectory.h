#pragma once
// Test support: a new, empty directory of the test's own under the system's temporary
// directory, named `prefix` plus random characters (mkdtemp). Throws when it cannot be made.
#include <filesystem>
#include <string>

namespace tlmhub::test {

std::filesystem::path makeTemporaryDirectory(const std::string& prefix);

} // namespace tlmhub::test
