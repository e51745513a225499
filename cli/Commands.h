#pragma once
#include <string>
#include <vector>

namespace tlmhub::cli {

int runCommand(const std::vector<std::string>& args);
int validateCommand(const std::vector<std::string>& args);
int infoCommand(const std::vector<std::string>& args);
int componentsCommand(const std::vector<std::string>& args);
int benchCommand(const std::vector<std::string>& args);
int batchCommand(const std::vector<std::string>& args);
// `fmu MODEL.hmf -o OUT.fmu`: the model as an FMI 2.0 co-simulation FMU; argv0 helps find
// the runtime library when /proc/self/exe cannot be read.
int fmuCommand(const std::vector<std::string>& args, const std::string& argv0);
// `remote SUBCOMMAND ...`: the server's REST API (cli/remote/).
int remoteCommand(const std::vector<std::string>& args);

} // namespace tlmhub::cli
