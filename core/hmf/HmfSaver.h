#pragma once
// Saving a System as a Hopsan model file (.hmf 0.4). Content the core does not interpret
// (GUI data) that was read from a file is written back unchanged.
#include "core/System.h"

#include <string>

namespace tlmhub {

std::string saveHmfString(const System& root);
Status saveHmfFile(const System& root, const std::string& path);

} // namespace tlmhub
