#include "cli/Commands.h"

#include "core/Validation.h"

#include <cstdio>
#include <iostream>

namespace tlmhub::cli {

int validateCommand(const std::vector<std::string>& args)
{
    if (args.empty()) {
        std::cerr << "tlmhub-cli validate: expected one or more .hvc files\n";
        return 2;
    }
    std::size_t passed = 0, failed = 0;
    for (const std::string& path : args) {
        ValidationReport report = validateHvc(path);
        std::printf("== %s\n", path.c_str());
        if (!report.error.empty()) {
            std::printf("FAIL  %s\n", report.error.c_str());
            ++failed;
        }
        for (const auto& v : report.variables) {
            if (v.error.empty())
                std::printf("%s  %-60s worst deviation %.3e at t=%g (tolerance %g)\n",
                            v.passed ? "PASS" : "FAIL", v.name.c_str(), v.worstDeviation, v.worstTime,
                            v.tolerance);
            else
                std::printf("FAIL  %-60s %s\n", v.name.c_str(), v.error.c_str());
            v.passed ? ++passed : ++failed;
        }
    }
    std::printf("%zu passed, %zu failed\n", passed, failed);
    return failed == 0 && passed > 0 ? 0 : 1;
}

} // namespace tlmhub::cli
