// tlmhub-cli: run a Hopsan model, write CSV, validate an .hvc, describe models and components,
// export a model as an FMU;
// `remote` runs models on a tlmhub server.
#include "cli/Commands.h"
#include "fmu/FmuLoadPolicy.h"

#include <cstring>
#include <iostream>
#include <string>

namespace {

void usage(std::ostream& os)
{
    os << "usage:\n"
          "  tlmhub-cli run MODEL.hmf [--start S --step H --stop T] [--samples N] [--threads N|auto]\n"
          "                 [--csv OUT.csv] [--sha256] [--check-finite]\n"
          "  tlmhub-cli validate FILE.hvc [FILE.hvc ...]\n"
          "  tlmhub-cli info MODEL.hmf\n"
          "  tlmhub-cli components [--json]\n"
          "  tlmhub-cli bench MODEL.hmf [--repeat K] [--threads N|auto[,...]] [--vary Comp.param=a:b:n]\n"
          "  tlmhub-cli batch MODEL.hmf [MODEL.hmf ...] [--copies K] [--threads N]\n"
          "  tlmhub-cli fmu MODEL.hmf -o OUT.fmu [--parameter Comp.param]... [--identifier NAME]\n"
          "  tlmhub-cli remote login|run|sweep|sensitivity|optimise|jobs|results|studies ...   (tlmhub-cli remote --help)\n";
}

} // namespace

int main(int argc, char** argv)
{
    if (argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h")) {
        usage(argc < 2 ? std::cerr : std::cout);
        return argc < 2 ? 2 : 0;
    }
    const std::string command = argv[1];
    // The user runs their own models: an FMU a model names loads from wherever it is.
    tlmhub::fmu::setFmuLoadPolicy(tlmhub::fmu::FmuLoadPolicy::anywhere());
    std::vector<std::string> args(argv + 2, argv + argc);
    try {
        if (command == "run") return tlmhub::cli::runCommand(args);
        if (command == "validate") return tlmhub::cli::validateCommand(args);
        if (command == "info") return tlmhub::cli::infoCommand(args);
        if (command == "components") return tlmhub::cli::componentsCommand(args);
        if (command == "bench") return tlmhub::cli::benchCommand(args);
        if (command == "batch") return tlmhub::cli::batchCommand(args);
        if (command == "fmu") return tlmhub::cli::fmuCommand(args, argv[0]);
        if (command == "remote") return tlmhub::cli::remoteCommand(args);
    } catch (const std::exception& e) {
        std::cerr << "tlmhub-cli: " << e.what() << "\n";
        return 1;
    }
    std::cerr << "tlmhub-cli: unknown command '" << command << "'\n";
    usage(std::cerr);
    return 2;
}
