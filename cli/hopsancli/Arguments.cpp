// hopsancli's options: one table, read by the parser and by the usage text.
#include "cli/hopsancli/HopsanCli.h"

#include <iostream>

namespace tlmhub::hopsancli {

namespace {

using K = OptionKind;
using S = Support;

// HopsanCLI 2.24's options (its main.cpp), in the order its usage lists them.
const std::vector<OptionSpec> kOptions = {
    {"m", "hmf", K::Value, S::Supported, "FILE", "model file (.hmf) to load"},
    {"s", "simulate", K::Value, S::Supported, "TIMES",
     "simulate the model: 'hmf' (the file's times), 'stop', 'step,stop' or 'start,step,stop'"},
    {"l", "numLogSamples", K::Value, S::Supported, "N", "log samples of the root system (default: the file's)"},
    {"p", "parallel", K::Value, S::Supported, "THREADS", "simulate on THREADS threads; 0 chooses automatically"},
    {"", "logonly", K::Value, S::Supported, "NAMES",
     "export only these ports or variables: a file with one full name a line, or names separated by commas"},
    {"", "parameterImport", K::Value, S::Supported, "FILE", "set parameters from 'Name,value' lines before the run"},
    {"", "parameterExport", K::Value, S::Supported, "FILE", "write every parameter as a 'Name,value' line"},
    {"", "resultsFullCSV", K::Value, S::Supported, "FILE", "write every logged sample"},
    {"", "resultsFinalCSV", K::Value, S::Supported, "FILE", "write the values at the end of the run"},
    {"", "resultsCSVSort", K::Value, S::Supported, "rows|cols", "one variable per line (rows, default) or per column"},
    {"", "prefixRootSystemName", K::Switch, S::Supported, "", "put 'RootName$' before exported parameter names"},
    {"d", "destination", K::Value, S::Supported, "DIR", "directory the exported files are written to"},
    {"t", "validate", K::Value, S::Supported, "FILE", "check the model an .hvc file names against its reference data"},
    {"", "silent", K::Switch, S::Supported, "", "print nothing on stdout"},
    {"", "endPause", K::Switch, S::Supported, "", "wait for Enter before exiting"},
    {"e", "externalLib", K::Repeatable, S::NoEffect, "LIB",
     "accepted; tlmhub's built-in component library is used"},
    {"", "externalLibsFile", K::Value, S::NoEffect, "FILE", "accepted; tlmhub's built-in component library is used"},
    {"", "printDebug", K::Switch, S::NoEffect, "", "accepted; no effect"},
    {"", "log.corelogfile", K::Value, S::NoEffect, "FILE", "accepted; no core log file is written"},
    {"", "resultsFullHDF5", K::Value, S::Refused, "FILE", "not supported (HDF5 export)"},
    {"", "resultsFinalHDF5", K::Value, S::Refused, "FILE", "not supported (HDF5 export)"},
    {"", "saveSimState", K::Value, S::Refused, "FILE", "not supported"},
    {"", "loadSimState", K::Value, S::Refused, "FILE", "not supported"},
    {"", "loadSimStartValues", K::Value, S::Refused, "FILE", "not supported"},
    {"", "createValidationData", K::Switch, S::Refused, "", "not supported"},
    {"", "testInstanciateComponents", K::Switch, S::Refused, "", "not supported"},
    {"", "buildComponentLibrary", K::Value, S::Refused, "FILE", "not supported"},
    {"o", "optScript", K::Repeatable, S::Refused, "FILE", "not supported (optimisation)"},
    {"", "optSettings", K::Repeatable, S::Refused, "SETTING", "not supported (optimisation)"},
};

const char* kProgram = "hopsancli";

// How HopsanCLI's parser names an option in its messages: "-m (--hmf)" or "(--silent)".
std::string displayName(const OptionSpec& spec)
{
    std::string s;
    if (*spec.shortName) s = std::string("-") + spec.shortName + " ";
    return s + "(--" + spec.longName + ")";
}

std::string briefForm(const OptionSpec& spec)
{
    std::string s = *spec.shortName ? std::string("-") + spec.shortName : std::string("--") + spec.longName;
    if (spec.kind != K::Switch) s += std::string(" <") + spec.valueName + ">";
    if (spec.kind == K::Repeatable) s += " ...";
    return "[" + s + "]";
}

void briefUsage(std::ostream& os)
{
    std::string line = std::string("   ") + kProgram;
    for (const OptionSpec& spec : kOptions) {
        const std::string part = briefForm(spec);
        if (line.size() + 1 + part.size() > 78) {
            os << line << "\n";
            line = "      ";
        }
        line += " " + part;
    }
    os << line << " [--] [--version] [-h]\n";
}

void fullUsage(std::ostream& os)
{
    os << "\nUSAGE:\n\n";
    briefUsage(os);
    os << "\nWhere:\n\n";
    for (const OptionSpec& spec : kOptions) {
        os << "   ";
        if (*spec.shortName) os << "-" << spec.shortName << " ";
        os << (*spec.shortName ? "<" : "") << "--" << spec.longName;
        if (spec.kind != K::Switch) os << " <" << spec.valueName << ">";
        if (*spec.shortName) os << ">";
        os << "\n     " << spec.help << (spec.kind == K::Repeatable ? " (may be given more than once)" : "")
           << "\n\n";
    }
    os << "   --, --ignore_rest\n     ignore the arguments after this one\n\n"
          "   --version\n     print the version and exit\n\n"
          "   -h, --help\n     print this text and exit\n\n"
          "   tlmhub's HopsanCLI-compatible command line (docs/hopsancli.md)\n\n";
}

// HopsanCLI's parser's failure text on stderr; its exit code is 1.
int parseError(const std::string& argument, const std::string& message)
{
    std::cerr << "PARSE ERROR: Argument: " << argument << "\n             " << message << "\n\n"
              << "Brief USAGE: \n";
    briefUsage(std::cerr);
    std::cerr << "\nFor complete USAGE and HELP type: \n   " << kProgram << " --help\n\n";
    return 1;
}

const OptionSpec* findOption(const std::string& arg)
{
    for (const OptionSpec& spec : kOptions) {
        if (arg.rfind("--", 0) == 0 ? arg.substr(2) == spec.longName
                                    : (*spec.shortName && arg == std::string("-") + spec.shortName))
            return &spec;
    }
    return nullptr;
}

} // namespace

const std::vector<OptionSpec>& optionTable() { return kOptions; }

std::string Arguments::value(const std::string& longName, const std::string& fallback) const
{
    auto it = given.find(longName);
    return it == given.end() || it->second.empty() ? fallback : it->second.front();
}

const std::vector<std::string>& Arguments::values(const std::string& longName) const
{
    static const std::vector<std::string> none;
    auto it = given.find(longName);
    return it == given.end() ? none : it->second;
}

ParseOutcome parseArguments(int argc, char** argv, Arguments& out, int& exitCode)
{
    exitCode = 0;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--" || arg == "--ignore_rest") break;
        if (arg == "-h" || arg == "--help") {
            fullUsage(std::cout);
            return ParseOutcome::Exit;
        }
        if (arg == "--version") {
            std::cout << "\n" << kProgram << "  version: tlmhub, with the options of HopsanCLI 2.24\n\n";
            return ParseOutcome::Exit;
        }
        const OptionSpec* spec = arg.size() > 1 && arg[0] == '-' ? findOption(arg) : nullptr;
        if (!spec) {
            exitCode = parseError(arg, "Couldn't find match for argument");
            return ParseOutcome::Exit;
        }
        auto& values = out.given[spec->longName];
        if (!values.empty() && spec->kind != K::Repeatable) {
            exitCode = parseError(displayName(*spec), "Argument already set!");
            return ParseOutcome::Exit;
        }
        if (spec->kind == K::Switch) {
            values.emplace_back();
            continue;
        }
        // The next argument is the value, whatever it looks like ("-s -1,0.001,10").
        if (i + 1 >= argc) {
            exitCode = parseError(displayName(*spec), "Missing a value for this argument!");
            return ParseOutcome::Exit;
        }
        values.emplace_back(argv[++i]);
    }
    return ParseOutcome::Run;
}

void Printer::line(const std::string& text) const
{
    if (silent) return;
    std::fwrite(text.data(), 1, text.size(), stdout);
    std::fputc('\n', stdout);
}

std::vector<std::string> splitFields(const std::string& text, char delimiter)
{
    std::vector<std::string> fields;
    std::size_t begin = 0;
    while (begin < text.size()) {
        const std::size_t end = text.find(delimiter, begin);
        if (end == std::string::npos) {
            fields.push_back(text.substr(begin));
            break;
        }
        fields.push_back(text.substr(begin, end - begin));
        begin = end + 1;
    }
    return fields;
}

} // namespace tlmhub::hopsancli
