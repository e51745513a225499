// remote run: upload the model, run it as a job, wait, and fetch the result CSV.
#include "cli/remote/Arguments.h"
#include "cli/remote/RemoteCommands.h"
#include "cli/remote/Session.h"
#include "cli/remote/StudyRequest.h"

#include <cstdio>

namespace tlmhub::cli::remote {

int run(const std::vector<std::string>& argv)
{
    const Arguments args(argv, {"start", "step", "stop", "csv"}, {"param"}, {});
    if (args.positional().size() != 1) throw UsageError("run needs one model file");
    const std::string& model = args.positional()[0];
    nlohmann::json job = nlohmann::json::object();
    if (!args.values("param").empty()) job["parameters"] = parameterValues(args.values("param"));
    for (const char* setting : {"start", "step", "stop"})
        if (const std::optional<double> value = args.number(setting)) job[setting] = *value;

    ApiClient api = connectWithCredentials();
    const long long modelId = remote::modelId(api, model);
    job["model_id"] = modelId;
    const long long id = api.post("/jobs", job).at("id").get<long long>();
    const std::string path = "/jobs/" + std::to_string(id);
    const nlohmann::json info = waitUntilFinished(api, path, "job " + std::to_string(id));
    const std::string state = info.at("state").get<std::string>();
    if (state != "done") {
        const std::string reason = field(info, "error", std::string());
        std::fprintf(stderr, "error: job %lld %s%s%s\n", id, state.c_str(), reason.empty() ? "" : ": ", reason.c_str());
        return 1;
    }
    const std::string csv = args.value("csv");
    // --csv -: the result on standard output, the report on standard error.
    const bool onStandardOutput = csv == "-";
    if (onStandardOutput) writeStandardOutput(api.getText(path + "/results?format=csv"));
    else if (!csv.empty()) writeFile(csv, api.getText(path + "/results?format=csv"));
    const nlohmann::json settings = info.contains("settings") ? info["settings"] : nlohmann::json();
    std::fprintf(onStandardOutput ? stderr : stdout, "ok: %s: job %lld (model %lld), %lld steps, t=[%g, %g]%s%s\n",
                 model.c_str(), id, modelId, field(info, "steps", 0LL), field(settings, "start", 0.0),
                 field(settings, "stop", 0.0), csv.empty() ? "" : ", csv ",
                 onStandardOutput ? "on standard output" : csv.c_str());
    return 0;
}

} // namespace tlmhub::cli::remote
