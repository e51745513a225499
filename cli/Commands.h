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
// `remote SUBCOMMAND ...`: the server's REST API (cli/remote/).
int remoteCommand(const std::vector<std::string>& args);

} // namespace tlmhub::cli
