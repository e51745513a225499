// remote studies: the caller's studies; one shown, cancelled, resumed, or its table fetched.
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

// "/studies/ID" of the one positional argument of `studies COMMAND ID`.
std::string studyPath(const Arguments& args, const std::string& command)
{
    if (args.positional().size() != 1) throw UsageError("studies " + command + " needs one study id");
    const std::optional<double> id = parseNumber(args.positional()[0]);
    if (!id || *id < 1 || *id != static_cast<double>(static_cast<long long>(*id)))
        throw UsageError("studies " + command + " needs a study id (a whole number), got '" + args.positional()[0] + "'");
    return "/studies/" + std::to_string(static_cast<long long>(*id));
}

// The StudyInfo as the server gives it, indented.
int showStudy(const std::vector<std::string>& argv)
{
    const Arguments args(argv, {}, {}, {});
    const std::string path = studyPath(args, "show");
    ApiClient api = connectWithCredentials();
    writeStandardOutput(api.get(path).dump(2) + "\n");
    return 0;
}

// A queued or running study is cancelled; a finished one is left as it is (the same DELETE
// would delete it).
int cancelStudy(const std::vector<std::string>& argv)
{
    const Arguments args(argv, {}, {}, {});
    const std::string path = studyPath(args, "cancel");
    ApiClient api = connectWithCredentials();
    const std::string state = field(api.get(path), "state", std::string());
    if (state != "queued" && state != "running") {
        std::fprintf(stderr, "error: the study is %s: only a queued or running study is cancelled\n", state.c_str());
        return 1;
    }
    const nlohmann::json reply = api.del(path);
    std::printf("%s %s\n", path.substr(1).c_str(), field(reply, "state", std::string("cancelling")).c_str());
    return 0;
}

int studyResults(const std::vector<std::string>& argv)
{
    const Arguments args(argv, {"csv"}, {}, {});
    const std::string path = studyPath(args, "results");
    ApiClient api = connectWithCredentials();
    const std::string csv = api.getText(path + "/results?format=csv");
    if (args.has("csv") && args.value("csv") != "-") writeFile(args.value("csv"), csv);
    else writeStandardOutput(csv);
    return 0;
}

// Queues the study again; it runs only the runs it lacks. Prints what is left to run.
int resumeStudy(const std::vector<std::string>& argv)
{
    const Arguments args(argv, {}, {}, {});
    const std::string path = studyPath(args, "resume");
    ApiClient api = connectWithCredentials();
    const nlohmann::json study = api.post(path + "/resume", nlohmann::json::object());
    const long long finished = field(study, "runs_done", 0LL) + field(study, "runs_failed", 0LL);
    std::printf("study %lld resumed: %lld of %lld runs stored, the others run now\n", study.at("id").get<long long>(),
                finished, field(study, "runs_total", 0LL));
    return 0;
}

} // namespace

int studies(const std::vector<std::string>& args)
{
    if (args.empty()) throw UsageError("studies needs list, show, cancel, resume or results");
    const std::vector<std::string> rest(args.begin() + 1, args.end());
    if (args[0] == "list") return listStudies(rest);
    if (args[0] == "show") return showStudy(rest);
    if (args[0] == "cancel") return cancelStudy(rest);
    if (args[0] == "resume") return resumeStudy(rest);
    if (args[0] == "results") return studyResults(rest);
    throw UsageError("unknown studies command '" + args[0] + "' (list, show, cancel, resume or results)");
}

} // namespace tlmhub::cli::remote
