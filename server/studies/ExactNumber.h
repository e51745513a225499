#pragma once
// A double as text that reads back as the same double ("%.17g"): what a study sets as a
// parameter value and writes into its tables, as the result CSV writes its numbers.
#include <cstdio>
#include <string>

namespace tlmhub::server {

inline std::string exactNumber(double value)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", value);
    return text;
}

} // namespace tlmhub::server
