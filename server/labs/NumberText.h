#pragma once
// A number as the labs write it for people and CSV: printf's %g (six significant digits, no
// trailing zeros), the one form bounds, warnings and the gradebook share.
#include <cstdio>
#include <string>

namespace tlmhub::server {

inline std::string numberText(double value)
{
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

} // namespace tlmhub::server
