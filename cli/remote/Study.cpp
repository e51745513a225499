// remote sweep, sensitivity and optimise: upload the model, submit the study, wait, and fetch its
// table (one row per run).
#include "cli/remote/Arguments.h"
#include "cli/remote/RemoteCommands.h"
#include "cli/remote/Session.h"
#include "cli/remote/StudyRequest.h"

#include <cstdio>
#include <filesystem>
#include <limits>

namespace tlmhub::cli::remote {

namespace {

// `--csv -`: the table on standard output, as a Unix tool takes "-".
const std::string kStandardOutput = "-";

std::string modelName(const std::string& path) { return std::filesystem::path(path).stem().string(); }

// Submits `request` for the model file and waits; the finished StudyInfo, or nullopt after
// reporting a study that did not finish.
std::optional<nlohmann::json> runStudy(ApiClient& api, const std::string& model, nlohmann::json request)
{
    request["model_id"] = modelId(api, model);
    const long long id = api.post("/studies", request).at("id").get<long long>();
    nlohmann::json info = waitUntilFinished(api, "/studies/" + std::to_string(id), "study " + std::to_string(id));
    const std::string state = info.at("state").get<std::string>();
    if (state == "done") return info;
    const std::string reason = field(info, "error", std::string());
    std::fprintf(stderr, "error: study %lld %s%s%s\n", id, state.c_str(), reason.empty() ? "" : ": ", reason.c_str());
    return std::nullopt;
}

std::string table(ApiClient& api, const nlohmann::json& info)
{
    return api.getText("/studies/" + std::to_string(info.at("id").get<long long>()) + "/results?format=csv");
}

// The table where --csv says: on standard output without it or with "-" (for a pipe: true,
// and the command then prints no report), else in that file.
bool writeTable(ApiClient& api, const nlohmann::json& info, const std::string& csv)
{
    if (csv.empty() || csv == kStandardOutput) {
        writeStandardOutput(table(api, info));
        return true;
    }
    writeFile(csv, table(api, info));
    return false;
}

// "ok: MODEL: study ID, N runs, M failed" and `more`.
void reportDone(std::FILE* to, const std::string& model, const nlohmann::json& info, const std::string& more)
{
    std::fprintf(to, "ok: %s: study %lld, %lld runs, %lld failed%s\n", model.c_str(), info.at("id").get<long long>(),
                 field(info, "runs_done", 0LL), field(info, "runs_failed", 0LL), more.c_str());
}

} // namespace

int sweep(const std::vector<std::string>& argv)
{
    const Arguments args(argv, {"mode", "csv", "samples", "seed", "start", "step", "stop"}, {"vary", "output", "param"},
                         {"full"});
    if (args.positional().size() != 1) throw UsageError("sweep needs one model file");
    const std::string& model = args.positional()[0];
    const nlohmann::json request = sweepRequest(modelName(model), args);

    ApiClient api = connectWithCredentials();
    const std::optional<nlohmann::json> info = runStudy(api, model, request);
    if (!info) return 1;
    const std::string csv = args.value("csv");
    if (!writeTable(api, *info, csv)) reportDone(stdout, model, *info, ", table " + csv);
    return 0;
}

int sensitivity(const std::vector<std::string>& argv)
{
    const Arguments args(argv, {"runs", "seed", "csv", "bands", "start", "step", "stop"},
                         {"distribution", "output", "param"}, {"full"});
    if (args.positional().size() != 1) throw UsageError("sensitivity needs one model file");
    const std::string& model = args.positional()[0];
    const nlohmann::json request = sensitivityRequest(modelName(model), args);

    ApiClient api = connectWithCredentials();
    const std::optional<nlohmann::json> info = runStudy(api, model, request);
    if (!info) return 1;
    const std::string path = "/studies/" + std::to_string(info->at("id").get<long long>());
    if (args.has("bands")) writeFile(args.value("bands"), api.getText(path + "/bands?format=csv"));
    const std::string csv = args.value("csv");
    if (!writeTable(api, *info, csv))
        reportDone(stdout, model, *info, ", table " + csv + (args.has("bands") ? ", bands " + args.value("bands") : ""));
    return 0;
}

int optimise(const std::vector<std::string>& argv)
{
    const Arguments args(argv, {"algorithm", "max-evaluations", "seed", "tolerance", "csv", "start", "step", "stop"},
                         {"bound", "objective", "param"}, {"maximise"});
    if (args.positional().size() != 1) throw UsageError("optimise needs one model file");
    const std::string& model = args.positional()[0];
    const nlohmann::json request = optimiseRequest(modelName(model), args);

    ApiClient api = connectWithCredentials();
    const std::optional<nlohmann::json> info = runStudy(api, model, request);
    if (!info) return 1;
    const std::string csv = args.value("csv");
    // With --csv - the table is the standard output, and the report goes to standard error.
    const bool tableOnStandardOutput = csv == kStandardOutput;
    std::FILE* report = tableOnStandardOutput ? stderr : stdout;
    if (!csv.empty()) writeTable(api, *info, csv);
    const nlohmann::json summary = info->contains("summary") ? info->at("summary") : nlohmann::json();
    reportDone(report, model, *info,
               csv.empty() ? "" : ", table " + (tableOnStandardOutput ? std::string("on standard output") : csv));
    if (!summary.is_object() || !summary.contains("best")) {
        std::fprintf(stderr, "error: the study reports no best point\n");
        return 1;
    }
    const nlohmann::json& best = summary.at("best");
    // %.17g of the JSON's double: the digits read back to the same bits.
    std::fprintf(report, "best: run %lld, objective %.17g\n", field(best, "run", -1LL),
                 field(best, "objective", std::numeric_limits<double>::quiet_NaN()));
    if (best.contains("parameters") && best["parameters"].is_object())
        for (const auto& [name, value] : best["parameters"].items())
            std::fprintf(report, "  %s = %s\n", name.c_str(), value.dump().c_str());
    return 0;
}

} // namespace tlmhub::cli::remote
