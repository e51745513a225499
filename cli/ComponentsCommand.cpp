#include "cli/Commands.h"

#include "core/Catalogue.h"

#include <cstdio>
#include <iostream>

namespace tlmhub::cli {

int componentsCommand(const std::vector<std::string>& args)
{
    const bool json = !args.empty() && args[0] == "--json";
    const nlohmann::json catalogue = componentCatalogue();
    if (json) {
        std::cout << catalogue.dump(1) << "\n";
        return 0;
    }
    for (const auto& c : catalogue) {
        std::printf("%-50s %s  %s\n", c["type"].get<std::string>().c_str(),
                    c["kind"].get<std::string>().c_str(), c["domain"].get<std::string>().c_str());
        for (const auto& p : c["ports"])
            std::printf("    port  %-16s %-24s %s\n", p["name"].get<std::string>().c_str(),
                        p["nodetype"].get<std::string>().c_str(), p["porttype"].get<std::string>().c_str());
        for (const auto& p : c["parameters"])
            std::printf("    param %-24s = %-12s %s %s\n", p["name"].get<std::string>().c_str(),
                        p["default"].get<std::string>().c_str(), p["unit"].get<std::string>().c_str(),
                        p["description"].get<std::string>().c_str());
    }
    std::printf("%zu component types\n", catalogue.size());
    return 0;
}

} // namespace tlmhub::cli
