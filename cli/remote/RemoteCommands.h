#pragma once
// The subcommands of `tlmhub-cli remote` (RemoteCommand.cpp dispatches to them). Each throws
// UsageError for a command line it cannot take and another std::exception for a failure.
#include <string>
#include <vector>

namespace tlmhub::cli::remote {

int login(const std::vector<std::string>& args);
int run(const std::vector<std::string>& args);
int sweep(const std::vector<std::string>& args);
int sensitivity(const std::vector<std::string>& args);
int optimise(const std::vector<std::string>& args);
int jobs(const std::vector<std::string>& args);
int results(const std::vector<std::string>& args);
int studies(const std::vector<std::string>& args);

} // namespace tlmhub::cli::remote
