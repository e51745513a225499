// `tlmhub-cli remote`: the server's REST API from the command line (docs/studies.md).
#include "cli/Commands.h"
#include "cli/remote/ApiClient.h"
#include "cli/remote/Arguments.h"
#include "cli/remote/RemoteCommands.h"

#include <algorithm>
#include <iostream>

namespace tlmhub::cli {

namespace {

void remoteUsage(std::ostream& os)
{
    os << "usage:\n"
          "  tlmhub-cli remote login URL [--user NAME] [--token-name NAME] [--password-stdin]\n"
          "  tlmhub-cli remote run MODEL.hmf [--param Comp.P=value]... [--start S --step H --stop T] [--csv OUT.csv]\n"
          "  tlmhub-cli remote sweep MODEL.hmf --vary Comp.P=from:to:steps | --vary Comp.P=v1,v2,... "
          "[--mode grid|list]\n"
          "                          | --mode random --samples N [--seed S] --vary Comp.P=from:to\n"
          "                          [--output VARIABLE:final,max,...]... [--full] [--csv TABLE.csv|-]\n"
          "                          [--param Comp.P=value]... [--start S --step H --stop T]\n"
          "  tlmhub-cli remote sensitivity MODEL.hmf --runs N --distribution Comp.P=normal:MEAN:SD|uniform:MIN:MAX...\n"
          "                          --output VARIABLE:final,max,... [--seed S] [--full] [--csv TABLE.csv|-]\n"
          "                          [--bands BANDS.csv] [--param Comp.P=value]... [--start S --step H --stop T]\n"
          "  tlmhub-cli remote optimise MODEL.hmf --bound Comp.P=min:max... "
          "--objective FUNCTION:VARIABLE[:REFERENCE_VARIABLE][*WEIGHT]...\n"
          "                          [--algorithm complex-rf|nelder-mead|particle-swarm] [--maximise]\n"
          "                          [--max-evaluations N] [--seed S] [--tolerance X] [--csv TABLE.csv|-]\n"
          "                          [--param Comp.P=value]... [--start S --step H --stop T]\n"
          "  tlmhub-cli remote jobs\n"
          "  tlmhub-cli remote results JOB_ID [--csv OUT.csv] [--variables a,b]\n"
          "  tlmhub-cli remote studies list | show ID | cancel ID | resume ID | results ID [--csv TABLE.csv|-]\n"
          "MODEL.hmf is a file, uploaded as a model named after it, or a stored model's id (nothing uploaded).\n"
          "The server and token come from 'remote login' ($XDG_CONFIG_HOME/tlmhub/credentials or\n"
          "~/.config/tlmhub/credentials), or TLMHUB_URL and TLMHUB_TOKEN.\n";
}

int dispatch(const std::string& command, const std::vector<std::string>& args)
{
    if (command == "login") return remote::login(args);
    if (command == "run") return remote::run(args);
    if (command == "sweep") return remote::sweep(args);
    if (command == "sensitivity") return remote::sensitivity(args);
    if (command == "optimise") return remote::optimise(args);
    if (command == "jobs") return remote::jobs(args);
    if (command == "results") return remote::results(args);
    if (command == "studies") return remote::studies(args);
    throw remote::UsageError("unknown remote command '" + command + "'");
}

} // namespace

int remoteCommand(const std::vector<std::string>& args)
{
    const bool help = std::find(args.begin(), args.end(), "--help") != args.end() ||
                      std::find(args.begin(), args.end(), "-h") != args.end();
    if (args.empty() || help) {
        remoteUsage(args.empty() ? std::cerr : std::cout);
        return args.empty() ? 2 : 0;
    }
    try {
        return dispatch(args[0], std::vector<std::string>(args.begin() + 1, args.end()));
    } catch (const remote::UsageError& e) {
        std::cerr << "tlmhub-cli remote " << args[0] << ": " << e.what() << "\n";
        remoteUsage(std::cerr);
        return 2;
    } catch (const remote::ApiError& e) {
        std::cerr << "error: " << e.what() << "\n";
        if (e.status() == 401 && args[0] != "login")
            std::cerr << "(log in again with 'tlmhub-cli remote login URL', or check TLMHUB_TOKEN)\n";
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "error: " << e.what() << "\n";
        return 1;
    }
}

} // namespace tlmhub::cli
