#pragma once
// "--threads" values of tlmhub-cli: a count (1 to 256) or "auto" (RunOptions::autoThreads).
#include <optional>
#include <string>

namespace tlmhub::cli {

std::optional<unsigned> parseThreadCount(const std::string& text);
// "auto" or the count.
std::string threadCountName(unsigned threads);

} // namespace tlmhub::cli
