#pragma once
// What a model's name may be. Names are shown in lists, window titles and download file
// names, so control characters (NUL, line breaks) and bidirectional overrides, which make a
// name display as something else, are refused, as is text that is not UTF-8.
#include <cstddef>
#include <string>

namespace tlmhub::server {

inline constexpr std::size_t kMaxModelNameBytes = 200;

// Empty when `name` is acceptable, else what is wrong with it.
std::string modelNameProblem(const std::string& name);

// The same rules on characters alone, for other names shown in lists (API tokens): empty
// when `name` is valid UTF-8 without control or bidirectional control characters.
std::string nameCharacterProblem(const std::string& name);

} // namespace tlmhub::server
