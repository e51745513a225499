#pragma once
// The remote commands' arguments: positional ones and declared options, "--name value" or
// "--name=value", some repeatable (--param, --vary, ...), and flags. Unlike cli/Options.h,
// which guesses whether "--name" takes a value, each command declares its options, so a flag
// never swallows the model file after it and a misspelt option is an error.
#include <initializer_list>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace tlmhub::cli::remote {

// A command line the command cannot take: exit status 2 with the usage text.
class UsageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class Arguments {
public:
    // Throws UsageError for an undeclared option, a missing value, or a single-valued option
    // given twice.
    Arguments(const std::vector<std::string>& args, std::initializer_list<std::string_view> single,
              std::initializer_list<std::string_view> repeated, std::initializer_list<std::string_view> flags);

    const std::vector<std::string>& positional() const { return mPositional; }
    bool has(const std::string& name) const { return mValues.count(name) != 0; }
    // The option's value, or "" when absent.
    std::string value(const std::string& name) const;
    // Every value of a repeatable option, in command-line order.
    const std::vector<std::string>& values(const std::string& name) const;
    // The option as a number; nullopt when absent; UsageError when not a number.
    std::optional<double> number(const std::string& name) const;

private:
    std::vector<std::string> mPositional;
    std::map<std::string, std::vector<std::string>> mValues;   // a flag has one "" value
};

// `text` as a number, nothing else around it.
std::optional<double> parseNumber(const std::string& text);

} // namespace tlmhub::cli::remote
