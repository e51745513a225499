// remote jobs and remote results: the caller's jobs, and one job's result CSV.
#include "cli/remote/Arguments.h"
#include "cli/remote/RemoteCommands.h"
#include "cli/remote/Session.h"

#include <cstdio>
#include <ctime>

namespace tlmhub::cli::remote {

namespace {

// Unix seconds as "2026-12-03 12:00:01" (UTC); "-" for none (negative).
std::string utcTime(long long seconds)
{
    if (seconds < 0) return "-";
    const std::time_t t = static_cast<std::time_t>(seconds);
    std::tm parts{};
    char text[32];
    if (!::gmtime_r(&t, &parts) || !std::strftime(text, sizeof text, "%Y-%m-%d %H:%M:%S", &parts)) return "-";
    return text;
}

} // namespace

int jobs(const std::vector<std::string>& argv)
{
    const Arguments args(argv, {}, {}, {});
    if (!args.positional().empty()) throw UsageError("jobs takes no arguments");
    ApiClient api = connectWithCredentials();
    const nlohmann::json list = api.get("/jobs");
    std::printf("%8s  %-11s  %8s  %8s  %10s  %-19s  %s\n", "ID", "STATE", "PROGRESS", "MODEL", "STEPS",
                "CREATED (UTC)", "ERROR");
    for (const nlohmann::json& job : list) {
        const long long model = field(job, "model_id", -1LL);
        std::printf("%8lld  %-11s  %6.0f %%  %8s  %10lld  %-19s  %s\n", job.at("id").get<long long>(),
                    field(job, "state", std::string("?")).c_str(), field(job, "progress", 0.0) * 100,
                    model < 0 ? "-" : std::to_string(model).c_str(), field(job, "steps", 0LL),
                    utcTime(field(job, "created_at", -1LL)).c_str(), field(job, "error", std::string()).c_str());
    }
    return 0;
}

int results(const std::vector<std::string>& argv)
{
    const Arguments args(argv, {"csv", "variables"}, {}, {});
    if (args.positional().size() != 1) throw UsageError("results needs one job id");
    const std::optional<double> id = parseNumber(args.positional()[0]);
    if (!id || *id < 1 || *id != static_cast<double>(static_cast<long long>(*id)))
        throw UsageError("results needs a job id (a whole number), got '" + args.positional()[0] + "'");
    std::string path = "/jobs/" + std::to_string(static_cast<long long>(*id)) + "/results?format=csv";
    if (args.has("variables")) path += "&variables=" + percentEncode(args.value("variables"));
    ApiClient api = connectWithCredentials();
    const std::string csv = api.getText(path);
    if (args.has("csv") && args.value("csv") != "-") writeFile(args.value("csv"), csv);
    else writeStandardOutput(csv);
    return 0;
}

} // namespace tlmhub::cli::remote
