#include "fmu/Guid.h"

#include "core/Sha256.h"

namespace tlmhub::fmu {

std::string guidOfModel(std::string_view hmfText, const std::vector<std::string>& parameterPaths)
{
    Sha256 hash;
    hash.update(hmfText);
    for (const std::string& path : parameterPaths) {
        hash.update("\n");
        hash.update(path);
    }
    const std::string hex = hash.hexDigest();
    return "{" + hex.substr(0, 8) + "-" + hex.substr(8, 4) + "-" + hex.substr(12, 4) + "-" + hex.substr(16, 4) +
           "-" + hex.substr(20, 12) + "}";
}

} // namespace tlmhub::fmu
