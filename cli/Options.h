#pragma once
// Minimal "--name value" option parsing for tlmhub-cli.
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

namespace tlmhub::cli {

struct Options {
    std::vector<std::string> positional;
    std::map<std::string, std::string> named;   // --name value, or --flag -> ""

    explicit Options(const std::vector<std::string>& args)
    {
        for (std::size_t i = 0; i < args.size(); ++i) {
            const std::string& a = args[i];
            if (a.rfind("--", 0) == 0) {
                std::string name = a.substr(2);
                if (i + 1 < args.size() && args[i + 1].rfind("--", 0) != 0) named[name] = args[++i];
                else named[name] = "";
            } else {
                positional.push_back(a);
            }
        }
    }

    bool has(const std::string& name) const { return named.count(name) != 0; }
    std::string value(const std::string& name) const
    {
        auto it = named.find(name);
        return it == named.end() ? std::string() : it->second;
    }
    // Parse --name as a number if present; false with an error if it is not a number.
    bool number(const std::string& name, double& out, std::string& error) const
    {
        auto it = named.find(name);
        if (it == named.end()) return true;
        char* end = nullptr;
        double v = std::strtod(it->second.c_str(), &end);
        if (it->second.empty() || *end != '\0') {
            error = "--" + name + " needs a number, got '" + it->second + "'";
            return false;
        }
        out = v;
        return true;
    }
};

} // namespace tlmhub::cli
