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
    std::string guid = "{";
    for (std::size_t i = 0; i < 32; ++i) {
        if (i == 8 || i == 12 || i == 16 || i == 20)
            guid += '-';
        guid += hex[i];
    }
    guid += '}';
    return guid;
}

} // namespace tlmhub::fmu
