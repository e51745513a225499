#pragma once
// The GUID of an exported FMU: derived from what the FMU runs (the model text and the
// component parameters it offers), so exporting the same model twice gives the same GUID,
// and the runtime can check that its resources are the model its modelDescription.xml
// describes.
#include <string>
#include <string_view>
#include <vector>

namespace tlmhub::fmu {

// "{8-4-4-4-12 hex digits}" from the first 128 bits of the SHA-256 of the text followed by
// "\n<path>" for each offered component parameter.
std::string guidOfModel(std::string_view hmfText, const std::vector<std::string>& parameterPaths);

} // namespace tlmhub::fmu
