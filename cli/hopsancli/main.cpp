// hopsancli: HopsanCLI's command line on tlmhub's engine (docs/hopsancli.md). The steps and
// their order are HopsanCLI's: load the model (-m), import then export parameters, simulate
// (-s), write the result files, then validate (-t). Exit code 0 when the run (or the
// validation) succeeded, 1 otherwise, 255 for a negative thread count.
#include "cli/hopsancli/HopsanCli.h"

#include "core/Simulation.h"
#include "core/Validation.h"
#include "core/hmf/HmfLoader.h"
#include "fmu/FmuLoadPolicy.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <optional>

namespace tlmhub::hopsancli {

namespace {

constexpr int kSucceeded = 0;
constexpr int kFailed = 1;
constexpr int kNegativeThreads = 255;   // HopsanCLI's `return -1`

std::string shortNumber(double value)
{
    char text[64];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

void printMessages(const std::vector<Message>& messages, const Printer& print)
{
    for (const Message& m : messages) {
        const std::string where = m.source.empty() ? std::string() : m.source + ": ";
        if (m.type == MessageType::Warning) print.warning(where + m.text);
        else if (m.type == MessageType::Error || m.type == MessageType::Fatal) print.error(where + m.text);
    }
}

void printHierarchy(const System& system, const std::string& indent, const Printer& print)
{
    std::string head = indent + system.name() + ", Ts: " + shortNumber(system.desiredTimestep) +
                       " InheritTs: " + (system.inheritTimestep ? "1" : "0") + " ";
    for (const auto& p : system.parameters().all())
        if (!p->isStartValue) head += " SysParam: " + p->name + "=" + p->value;
    print.line(head);
    for (const Component* c : system.componentsByName()) {
        if (c->isSystem()) printHierarchy(*static_cast<const System*>(c), indent + "  ", print);
        else print.line(indent + "  " + c->name());
    }
}

// --logonly: a file with one name a line, or names separated by commas. Names that name no
// port are reported as HopsanCLI reports them.
std::vector<std::string> logOnlyNames(System& root, const std::string& fileOrList, const Printer& print)
{
    std::vector<std::string> names;
    if (std::ifstream file(fileOrList); file) {
        for (std::string line; std::getline(file, line);) {
            if (!line.empty() && line.back() == '\r') line.pop_back();
            if (!line.empty()) names.push_back(line);
        }
    } else {
        names = splitFields(fileOrList, ',');
    }
    for (const std::string& name : names) {
        const std::vector<std::string> parts = splitFields(name, '#');
        Component* c = parts.empty() ? nullptr : componentWithFullName(root, parts[0], print);
        if (c && parts.size() != 2 && parts.size() != 3)
            print.error("A portname on the format ComponentName#PortName could not be found: " + name);
        if (!c || parts.size() < 2 || parts.size() > 3 || !c->port(parts[1]))
            print.warning("Could not find port: '" + name + "' when processing logonly input");
    }
    return names;
}

void writeResults(const System& root, const Arguments& args, const std::string& option, ResultAmount amount,
                  const std::string& destination, const std::vector<std::string>& only, const Printer& print)
{
    if (!args.has(option)) return;
    const std::string path = destination + args.value(option);
    print.line(std::string(amount == ResultAmount::Full ? "Saving Full" : "Saving Final") +
               " results to file: " + path);
    const std::string sort = args.value("resultsCSVSort", "rows");
    const bool columns = sort == "cols";
    if (columns) print.line("Transposing CSV file");
    std::string error;
    if (!writeResultsCsv(root, path, amount, only, columns, error)) print.error(error);
    if (!columns && sort != "rows") print.error("Unknown CSV sorting format: " + sort);
}

// -m with what goes with it: kSucceeded when the simulation (-s) ran to its end.
int runModel(const Arguments& args, const std::string& destination, const Printer& print)
{
    const std::string modelPath = args.value("hmf");
    if (args.has("validate"))
        print.warning("-m is not used with -t (--validate): the .hvc file names its own model");
    print.line("Loading Hopsan Model File: " + modelPath);
    LoadedModel loaded = loadHmfFile(modelPath);
    printMessages(loaded.messages, print);
    if (loaded.hasErrors() || !loaded.root) {
        print.error("There were errors while loading the model");
        return kFailed;
    }
    System& root = *loaded.root;

    if (args.has("parameterImport")) {
        print.line("Importing parameter values from file: " + args.value("parameterImport"));
        importParameters(root, args.value("parameterImport"), print);
    }
    if (args.has("parameterExport")) {
        const std::string path = destination + args.value("parameterExport");
        print.line("Exporting parameter values to file: " + path);
        const std::string prefix = args.has("prefixRootSystemName") ? root.name() + "$" : std::string();
        if (std::string error; !exportParameters(root, path, prefix, error)) print.error(error);
    }
    print.line("");
    print.line("Model Hierarchy:");
    printHierarchy(root, "", print);
    print.line("");

    int outcome = kFailed;
    std::vector<std::string> only;
    std::optional<Simulation> simulation;
    if (args.has("simulate")) {
        double start = root.startTime, step = root.desiredTimestep, stop = root.stopTime;
        const std::string times = args.value("simulate");
        if (times != "hmf") {
            const std::vector<std::string> t = splitFields(times, ',');
            if (t.size() == 3) {
                start = std::atof(t[0].c_str());
                step = std::atof(t[1].c_str());
                stop = std::atof(t[2].c_str());
            } else if (t.size() == 2) {
                step = std::atof(t[0].c_str());
                stop = std::atof(t[1].c_str());
            } else if (t.size() == 1) {
                stop = std::atof(t[0].c_str());
            }
        }
        SimulationSettings settings{start, stop, step, std::nullopt};
        if (args.has("numLogSamples")) {
            const long samples = std::atol(args.value("numLogSamples").c_str());
            print.line("Setting nLogSamples to: " + std::to_string(static_cast<std::size_t>(samples)));
            settings.logSamples = static_cast<std::size_t>(samples);
        }
        if (args.has("logonly")) only = logOnlyNames(root, args.value("logonly"), print);
        RunOptions options;
        if (args.has("parallel")) {
            const int threads = std::atoi(args.value("parallel").c_str());
            if (threads < 0) {
                print.error("Number of threads cannot be negative.");
                return kNegativeThreads;
            }
            options.threads = threads == 0 ? RunOptions::autoThreads : static_cast<unsigned>(std::min(threads, 256));
        }
        Result<Simulation> compiled = compile(root, settings);
        if (!compiled) {
            print.error(describe(compiled.status()));
            print.error("Initialize failed, Simulation aborted!");
        } else {
            simulation.emplace(std::move(*compiled));
            print.line("Simulating: " + shortNumber(start) + " to " + shortNumber(stop) + " with Ts: " +
                       shortNumber(step) + "     Please Wait!");
            const Status ran = simulation->run(options);
            printMessages(simulation->messages(), print);
            if (ran) {
                outcome = kSucceeded;
            } else {
                print.error(describe(ran));
                print.error("Simulation was aborted!");
            }
        }
    }

    writeResults(root, args, "resultsFinalCSV", ResultAmount::Final, destination, only, print);
    writeResults(root, args, "resultsFullCSV", ResultAmount::Full, destination, only, print);
    return outcome;
}

// -t: core.md §7 on the .hvc's model; HopsanCLI's lines for each variable.
bool validate(const std::string& hvcPath, const Printer& print)
{
    const ValidationReport report = validateHvc(hvcPath);
    if (!report.error.empty()) print.error(report.error);
    for (const VariableCheck& v : report.variables) {
        if (v.passed) {
            print.line("Test successful: " + v.name + " 1 Cores");
            continue;
        }
        print.line("Validation data test failed: " + v.name + " 1 Cores");
        char detail[160];
        std::snprintf(detail, sizeof detail, "worst deviation %.3e at t=%g (tolerance %g)", v.worstDeviation,
                      v.worstTime, v.tolerance);
        print.error(v.name + ": " + (v.error.empty() ? std::string(detail) : v.error));
    }
    return report.allPassed();
}

int run(int argc, char** argv)
{
    Arguments args;
    int exitCode = 0;
    if (parseArguments(argc, argv, args, exitCode) == ParseOutcome::Exit) return exitCode;
    const Printer print{args.has("silent")};

    for (const OptionSpec& spec : optionTable()) {
        if (spec.support == Support::Refused && args.has(spec.longName)) {
            print.error(std::string("--") + spec.longName + " is not supported by hopsancli (tlmhub)");
            return kFailed;
        }
    }
    for (const std::string& lib : args.values("externalLib"))
        print.line("Note: not loading external library " + lib + ": tlmhub's built-in component library is used");
    if (args.has("externalLibsFile"))
        print.line("Note: not loading the libraries listed in " + args.value("externalLibsFile") +
                   ": tlmhub's built-in component library is used");

    std::string destination = args.value("destination");
    if (!destination.empty() && destination.back() != '/') destination += '/';

    int outcome = kFailed;
    if (args.has("hmf")) outcome = runModel(args, destination, print);
    if (outcome == kNegativeThreads) return outcome;
    if (args.has("validate")) {
        outcome = validate(args.value("validate"), print) ? kSucceeded : kFailed;
    } else {
        print.line("");
        print.line("HopsanCLI Done!");
    }
    std::fflush(stdout);
    if (args.has("endPause")) {
        print.line("Press ENTER to continue ...");
        std::fflush(stdout);
        std::string ignored;
        std::getline(std::cin, ignored);
    }
    return outcome;
}

} // namespace

} // namespace tlmhub::hopsancli

int main(int argc, char** argv)
{
    // The user runs their own models: an FMU a model names loads from wherever it is.
    tlmhub::fmu::setFmuLoadPolicy(tlmhub::fmu::FmuLoadPolicy::anywhere());
    try {
        return tlmhub::hopsancli::run(argc, argv);
    } catch (const std::exception& e) {
        std::printf("Error: %s\n", e.what());
        return 1;
    }
}
