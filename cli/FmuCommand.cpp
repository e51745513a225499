#include "cli/Commands.h"

#include "core/Parameter.h"
#include "core/hmf/HmfLoader.h"
#include "fmu/FmuExport.h"

#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>

namespace tlmhub::cli {

namespace {

struct FmuArguments {
    std::string model;
    std::string output;
    fmu::InterfaceOptions options;
};

// MODEL.hmf -o OUT.fmu [--parameter Comp.param]... [--identifier NAME]; the error if not.
std::string parseFmuArguments(const std::vector<std::string>& args, FmuArguments& parsed)
{
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        const bool takesValue = a == "-o" || a == "--output" || a == "--parameter" || a == "--identifier";
        if (takesValue && i + 1 >= args.size()) return a + " needs a value";
        if (a == "-o" || a == "--output") parsed.output = args[++i];
        else if (a == "--parameter") parsed.options.parameters.push_back(args[++i]);
        else if (a == "--identifier") parsed.options.modelIdentifier = args[++i];
        else if (a.rfind("-", 0) == 0) return "unknown option " + a;
        else if (parsed.model.empty()) parsed.model = a;
        else return "expected one model file";
    }
    if (parsed.model.empty() || parsed.output.empty()) return "expected MODEL.hmf -o OUT.fmu";
    return {};
}

} // namespace

int fmuCommand(const std::vector<std::string>& args, const std::string& argv0)
{
    FmuArguments parsed;
    if (const std::string error = parseFmuArguments(args, parsed); !error.empty()) {
        std::cerr << "tlmhub-cli fmu: " << error << "\n";
        return 2;
    }
    std::ifstream in(parsed.model, std::ios::binary);
    std::ostringstream text;
    if (!(in && text << in.rdbuf())) {
        std::cerr << "error: cannot read " << parsed.model << "\n";
        return 1;
    }
    const Result<std::filesystem::path> runtime = fmu::findFmuRuntime(argv0);
    if (!runtime) {
        std::cerr << "error: " << runtime.status().message() << "\n";
        return 1;
    }
    const Result<std::string> zip = fmu::exportFmu(text.str(), parsed.model, parsed.options, *runtime);
    if (!zip) {
        std::cerr << "error: " << parsed.model << ": " << describe(zip.status()) << "\n";
        return 1;
    }
    std::ofstream out(parsed.output, std::ios::binary | std::ios::trunc);
    if (!(out << *zip) || !out.flush()) {
        std::cerr << "error: cannot write " << parsed.output << "\n";
        return 1;
    }
    // The interface as the FMU's description has it (the same rules, so describe it again).
    LoadedModel loaded = loadHmfString(text.str(), std::filesystem::path(parsed.model).parent_path().string(),
                                       parsed.model);
    const Model model(std::move(loaded.root));
    Result<fmu::ModelInterface> interface = fmu::describeInterface(model.root(), parsed.options);
    if (interface) (void)fmu::takeInputStartsFromInitialisation(*interface, model);   // it did in exportFmu
    std::printf("ok: wrote %s (%zu bytes, model identifier %s)\n", parsed.output.c_str(), zip->size(),
                interface->description.modelIdentifier.c_str());
    for (const fmu::ScalarVariable& v : interface->description.variables)
        std::printf("  %-10s %3u %s%s%s\n", fmu::causalityName(v.causality), v.valueReference, v.name.c_str(),
                    v.start ? " = " : "", v.start ? formatNumber(*v.start).c_str() : "");
    return 0;
}

} // namespace tlmhub::cli
