#pragma once
// The component catalogue: every registered type with its kind, domain, ports and
// parameters, generated from the component code (configure()) itself.
#include <nlohmann/json.hpp>

namespace tlmhub {

nlohmann::json componentCatalogue();

} // namespace tlmhub
