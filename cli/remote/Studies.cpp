// remote studies: the caller's studies, and resuming one that was interrupted or cancelled.
#include "cli/remote/Arguments.h"
#include "cli/remote/RemoteCommands.h"
#include "cli/remote/Session.h"

#include <cstdio>

namespace tlmhub::cli::remote {

namespace {

int listStudies(const std::vector<std::string>& argv)
{
    const Arguments args(argv, {}, {}, {});
    if (!args.positional().empty()) throw UsageError("studies list takes no arguments");
    ApiClient api = connectWithCredentials();
    const nlohmann::json reply = api.get("/studies");
    std::printf("%8s  %-11s  %-11s  %8s  %8s  %8s  %s\n", "ID", "KIND", "STATE", "DONE", "FAILED", "TOTAL", "ERROR");
    for (const nlohmann::json& study : reply.value("studies", nlohmann::json::array())) {
        std::printf("%8lld  %-11s  %-11s  %8lld  %8lld  %8lld  %s\n", study.at("id").get<long long>(),
                    field(study, "kind", std::string("?")).c_str(), field(study, "state", std::string("?")).c_str(),
                    field(study, "runs_done", 0LL), field(study, "runs_failed", 0LL), field(study, "runs_total", 0LL),
                    field(study, "error", std::string()).c_str());
    }
    return 0;
}

// Queues the study again; it runs only the runs it lacks. Prints what is left to run.
int resumeStudy(const std::vector<std::string>& argv)
{
    const Arguments args(argv, {}, {}, {});
    if (args.positional().size() != 1) throw UsageError("studies resume needs one study id");
    const std::optional<double> id = parseNumber(args.positional()[0]);
    if (!id || *id < 1 || *id != static_cast<double>(static_cast<long long>(*id)))
        throw UsageError("studies resume needs a study id (a whole number), got '" + args.positional()[0] + "'");
    ApiClient api = connectWithCredentials();
    const nlohmann::json study =
        api.post("/studies/" + std::to_string(static_cast<long long>(*id)) + "/resume", nlohmann::json::object());
    const long long finished = field(study, "runs_done", 0LL) + field(study, "runs_failed", 0LL);
    std::printf("study %lld resumed: %lld of %lld runs stored, the others run now\n", study.at("id").get<long long>(),
                finished, field(study, "runs_total", 0LL));
    return 0;
}

} // namespace

int studies(const std::vector<std::string>& args)
{
    if (args.empty()) throw UsageError("studies needs list or resume");
    const std::vector<std::string> rest(args.begin() + 1, args.end());
    if (args[0] == "list") return listStudies(rest);
    if (args[0] == "resume") return resumeStudy(rest);
    throw UsageError("unknown studies command '" + args[0] + "' (list or resume)");
}

} // namespace tlmhub::cli::remote
