#include "cli/remote/Session.h"

#include "cli/remote/Credentials.h"
#include "cli/remote/ProgressDisplay.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <thread>

namespace tlmhub::cli::remote {

ApiClient connectWithCredentials()
{
    std::string error;
    const std::optional<Credentials> credentials = loadCredentials(error);
    if (!credentials) throw std::runtime_error(error);
    const std::optional<Url> url = parseUrl(credentials->url, error);
    if (!url) throw std::runtime_error(error + " (from TLMHUB_URL or '" + credentialsPath().string() + "')");
    return ApiClient(*url, credentials->token);
}

namespace {

// A model the caller can read with this name and exactly this text: a file run again runs
// the model stored the first time instead of storing one more copy.
std::optional<long long> storedCopy(ApiClient& api, const std::string& name, const std::string& text)
{
    for (const nlohmann::json& model : api.get("/models")) {
        if (model.value("name", std::string()) != name) continue;
        const long long id = model.at("id").get<long long>();
        if (api.getText("/models/" + std::to_string(id) + "?format=hmf") == text) return id;
    }
    return std::nullopt;
}

long long uploadModel(ApiClient& api, const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    if (!(in && text << in.rdbuf())) throw std::runtime_error("cannot read '" + path + "'");
    const std::string name = std::filesystem::path(path).stem().string();
    if (const auto stored = storedCopy(api, name, text.str())) return *stored;
    const nlohmann::json model = api.postXml("/models?name=" + percentEncode(name), text.str());
    return model.at("id").get<long long>();
}

} // namespace

long long modelId(ApiClient& api, const std::string& model)
{
    const bool digits = !model.empty() && model.find_first_not_of("0123456789") == std::string::npos;
    if (digits && !std::filesystem::exists(model)) return api.get("/models/" + model).at("id").get<long long>();
    return uploadModel(api, model);
}

nlohmann::json waitUntilFinished(ApiClient& api, const std::string& path, const std::string& label)
{
    using namespace std::chrono_literals;
    ProgressDisplay progress(label);
    // Short jobs finish within the first polls; long ones are asked once a second.
    std::chrono::milliseconds pause = 100ms;
    for (;;) {
        nlohmann::json info = api.get(path);
        const std::string state = info.at("state").get<std::string>();
        const bool final = state == "done" || state == "failed" || state == "cancelled" || state == "interrupted";
        std::string detail = state;
        if (info.contains("runs_total")) {
            detail = std::to_string(field(info, "runs_done", 0LL)) + "/" +
                     std::to_string(field(info, "runs_total", 0LL)) + " runs, " + state;
            if (const long long failed = field(info, "runs_failed", 0LL); failed > 0)
                detail += ", " + std::to_string(failed) + " failed";
        }
        progress.update(state == "done" ? 1.0 : field(info, "progress", 0.0), detail);
        if (final) return info;
        std::this_thread::sleep_for(pause);
        pause = std::min<std::chrono::milliseconds>(pause * 3 / 2, 1s);
    }
}

void writeFile(const std::string& path, const std::string& bytes)
{
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error("cannot write '" + path + "'");
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.close();
    if (!out) throw std::runtime_error("error writing '" + path + "'");
}

void writeStandardOutput(const std::string& bytes)
{
    if (std::fwrite(bytes.data(), 1, bytes.size(), stdout) != bytes.size() || std::fflush(stdout) != 0)
        throw std::runtime_error("error writing to standard output");
}

} // namespace tlmhub::cli::remote
