#include "cli/ThreadCount.h"

#include "core/Simulation.h"

#include <cstdlib>

namespace tlmhub::cli {

std::optional<unsigned> parseThreadCount(const std::string& text)
{
    if (text == "auto") return RunOptions::autoThreads;
    char* end = nullptr;
    const long count = std::strtol(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0' || count < 1 || count > 256) return std::nullopt;
    return static_cast<unsigned>(count);
}

std::string threadCountName(unsigned threads)
{
    return threads == RunOptions::autoThreads ? "auto" : std::to_string(threads);
}

} // namespace tlmhub::cli
