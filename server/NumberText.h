#pragma once
// Numbers written as text by the server, in the two forms it uses: numberText for people and
// the gradebook's CSV (printf's %g: six significant digits, no trailing zeros; lab bounds,
// warnings, grades), exactNumber for values that must read back as the same double (%.17g: a
// study's parameter values and result tables).
#include <cstdio>
#include <string>

namespace tlmhub::server {

namespace detail {
inline std::string printed(const char* format, double value)
{
    char text[32];
    std::snprintf(text, sizeof text, format, value);
    return text;
}
} // namespace detail

inline std::string numberText(double value) { return detail::printed("%g", value); }
inline std::string exactNumber(double value) { return detail::printed("%.17g", value); }

} // namespace tlmhub::server
