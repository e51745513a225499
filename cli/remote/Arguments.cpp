#include "cli/remote/Arguments.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>

namespace tlmhub::cli::remote {

namespace {

bool listed(std::initializer_list<std::string_view> names, const std::string& name)
{
    return std::find(names.begin(), names.end(), name) != names.end();
}

} // namespace

std::optional<double> parseNumber(const std::string& text)
{
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (text.empty() || std::isspace(static_cast<unsigned char>(text.front())) || *end != '\0') return std::nullopt;
    return value;
}

Arguments::Arguments(const std::vector<std::string>& args, std::initializer_list<std::string_view> single,
                     std::initializer_list<std::string_view> repeated, std::initializer_list<std::string_view> flags)
{
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& arg = args[i];
        if (arg.rfind("--", 0) != 0) {
            mPositional.push_back(arg);
            continue;
        }
        const std::size_t equals = arg.find('=');
        const std::string name = arg.substr(2, equals == std::string::npos ? std::string::npos : equals - 2);
        if (listed(flags, name)) {
            if (equals != std::string::npos) throw UsageError("--" + name + " takes no value");
            mValues[name] = {""};
            continue;
        }
        const bool once = listed(single, name);
        if (!once && !listed(repeated, name)) throw UsageError("unknown option --" + name);
        if (once && has(name)) throw UsageError("--" + name + " is given twice");
        if (equals != std::string::npos) {
            mValues[name].push_back(arg.substr(equals + 1));
        } else if (i + 1 < args.size()) {
            mValues[name].push_back(args[++i]);
        } else {
            throw UsageError("--" + name + " needs a value");
        }
    }
}

std::string Arguments::value(const std::string& name) const
{
    const auto it = mValues.find(name);
    return it == mValues.end() ? std::string() : it->second.front();
}

const std::vector<std::string>& Arguments::values(const std::string& name) const
{
    static const std::vector<std::string> none;
    const auto it = mValues.find(name);
    return it == mValues.end() ? none : it->second;
}

std::optional<double> Arguments::number(const std::string& name) const
{
    if (!has(name)) return std::nullopt;
    const std::optional<double> value = parseNumber(this->value(name));
    if (!value) throw UsageError("--" + name + " needs a number, got '" + this->value(name) + "'");
    return value;
}

} // namespace tlmhub::cli::remote
