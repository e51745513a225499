#include "cli/Commands.h"
#include "cli/Options.h"
#include "cli/ThreadCount.h"

#include "core/ResultTable.h"
#include "core/Results.h"
#include "core/Sha256.h"
#include "core/Simulation.h"
#include "core/ParameterPath.h"
#include "core/hmf/HmfLoader.h"

#include <chrono>
#include <cstdio>
#include <string_view>
#include <iostream>

namespace tlmhub::cli {

namespace {

bool writeCsv(const ResultTable& table, const std::string& path, std::string& error)
{
    std::FILE* f = std::fopen(path.c_str(), "w");
    if (!f) {
        error = "cannot write '" + path + "'";
        return false;
    }
    bool ok = true;
    table.writeCsv([&](std::string_view piece) {
        ok = ok && std::fwrite(piece.data(), 1, piece.size(), f) == piece.size();
    });
    ok = std::fclose(f) == 0 && ok;
    if (!ok) error = "error writing '" + path + "'";
    return ok;
}

// Every "--param Comp.P=value" in order (Options keeps one value per name).
std::vector<std::pair<std::string, std::string>> parameterOverrides(const std::vector<std::string>& args)
{
    std::vector<std::pair<std::string, std::string>> overrides;
    for (std::size_t i = 0; i + 1 < args.size(); ++i) {
        if (args[i] != "--param") continue;
        const std::string& assignment = args[++i];
        const std::size_t equals = assignment.find('=');
        overrides.emplace_back(assignment.substr(0, equals),
                               equals == std::string::npos ? std::string() : assignment.substr(equals + 1));
    }
    return overrides;
}

// As the server applies a job's overrides: system parameters first, since component values
// may refer to them.
Status applyOverrides(System& root, const std::vector<std::pair<std::string, std::string>>& overrides)
{
    for (const bool systemParameters : {true, false}) {
        for (const auto& [path, value] : overrides) {
            if ((path.find('.') == std::string::npos) != systemParameters) continue;
            if (Status set = setParameterValue(root, path, value); !set) return set;
        }
    }
    return {};
}

std::string csvSha256(const ResultTable& table)
{
    Sha256 hash;
    table.writeCsv([&](std::string_view piece) { hash.update(piece); });
    return hash.hexDigest();
}

} // namespace

int runCommand(const std::vector<std::string>& args)
{
    Options opt(args);
    if (opt.positional.size() != 1) {
        std::cerr << "tlmhub-cli run: expected one model file\n";
        return 2;
    }
    const std::string& path = opt.positional[0];
    LoadedModel loaded = loadHmfFile(path);
    if (loaded.hasErrors()) {
        std::cerr << "error: " << loaded.firstError() << "\n";
        return 1;
    }
    Model model(std::move(loaded.root));
    const auto overrides = parameterOverrides(args);
    for (const auto& [name, value] : overrides) {
        if (name.empty() || value.empty()) {
            std::cerr << "error: --param needs Comp.Param=value (or Name=value for a system parameter)\n";
            return 2;
        }
    }
    if (const Status set = applyOverrides(model.root(), overrides); !set) {
        std::cerr << "error: " << path << ": " << describe(set) << "\n";
        return 1;
    }
    const System& root = model.root();
    double start = root.startTime, stop = root.stopTime, step = root.desiredTimestep;
    double samples = static_cast<double>(root.requestedLogSamples);
    std::string err;
    if (!opt.number("start", start, err) || !opt.number("stop", stop, err) ||
        !opt.number("step", step, err) || !opt.number("samples", samples, err)) {
        std::cerr << "error: " << err << "\n";
        return 2;
    }
    const std::optional<unsigned> threads = parseThreadCount(opt.has("threads") ? opt.value("threads") : "auto");
    if (!threads) {
        std::cerr << "error: --threads needs a count from 1 to 256 or auto, got '" << opt.value("threads") << "'\n";
        return 2;
    }
    if (!(stop >= start) || !(step > 0.0)) {
        std::cerr << "error: need stop >= start and a positive time step\n";
        return 2;
    }
    const std::string csv = opt.value("csv");
    const bool wantsHash = opt.has("sha256");
    // The run is of a copy of the model (compile(const Model&)). With --sha256, also reset and
    // continue a run from half time, and run the loaded model itself: the same results.
    const bool checkRerun = opt.has("check-rerun");
    SimulationSettings settings{start, stop, step, static_cast<std::size_t>(samples)};
    if ((!csv.empty() || wantsHash) && *settings.logSamples == 0) settings.logSamples = 1024;

    const auto t0 = std::chrono::steady_clock::now();
    Result<Simulation> compiled = compile(model, settings);
    if (!compiled) {
        std::cerr << "error: " << path << ": " << describe(compiled.status()) << "\n";
        return 1;
    }
    Simulation& sim = *compiled;
    const RunOptions runOptions{.threads = *threads};
    const auto t1 = std::chrono::steady_clock::now();
    const Status status = sim.run(runOptions);
    const auto t2 = std::chrono::steady_clock::now();
    for (const auto& m : sim.messages())
        if (m.type == MessageType::Error || m.type == MessageType::Fatal)
            std::cerr << "error: " << m.text << "\n";
    // A model that ends its own run (SignalStopSimulation) ran as designed: its results are
    // checked and written as those of a run to the stop time.
    const bool ended = status.code() == StatusCode::SimulationEnded;
    if (ended)
        std::fprintf(stderr, "note: %s: %s (t=%g, before the stop time %g)\n", path.c_str(),
                     status.message().c_str(), sim.time(), stop);
    if (!status && !ended) {
        if (status.code() == StatusCode::SimulationStopped)
            std::fprintf(stderr, "error: %s: simulation stopped at t=%g before the stop time %g\n",
                         path.c_str(), sim.time(), stop);
        else
            std::fprintf(stderr, "error: %s: %s\n", path.c_str(), describe(status).c_str());
        return 1;
    }
    std::string where;
    if (opt.has("check-finite") && findNonFinite(sim.system(), where)) {
        std::cerr << "error: " << path << ": non-finite value: " << where << "\n";
        return 1;
    }
    std::string hashNote;
    if (!csv.empty() || wantsHash) {
        const ResultTable table = ResultTable::fromView(sim.results());
        if (!csv.empty() && !writeCsv(table, csv, err)) {
            std::cerr << "error: " << err << "\n";
            return 1;
        }
        if (wantsHash) {
            const std::string hash = csvSha256(table);
            if (checkRerun) {
                const double half = start + 0.5 * (stop - start);
                Status again = sim.reset();
                if (again) again = sim.run(half, runOptions);
                if (again) again = sim.run(stop, runOptions);
                if (again.code() == StatusCode::SimulationEnded) again = Status::ok();
                const std::string rerunHash =
                    again ? csvSha256(ResultTable::fromView(sim.results())) : std::string();
                if (rerunHash != hash) {
                    std::fprintf(stderr,
                                 "error: %s: reset and a run continued from t=%g give csv sha256 %s, "
                                 "one fresh run %s (%s)\n",
                                 path.c_str(), half, rerunHash.c_str(), hash.c_str(),
                                 again ? "results differ" : describe(again).c_str());
                    return 1;
                }
                Result<Simulation> original = compile(std::move(model), settings);
                Status ran = original ? original->run(runOptions) : original.status();
                if (ran.code() == StatusCode::SimulationEnded) ran = Status::ok();
                const std::string originalHash =
                    ran ? csvSha256(ResultTable::fromView(original->results())) : std::string();
                if (originalHash != hash) {
                    std::fprintf(stderr,
                                 "error: %s: the loaded model gives csv sha256 %s, its copy %s (%s)\n",
                                 path.c_str(), originalHash.c_str(), hash.c_str(),
                                 ran ? "results differ" : describe(ran).c_str());
                    return 1;
                }
            }
            hashNote = ", csv sha256 " + hash;
        }
    }
    const double init = std::chrono::duration<double>(t1 - t0).count();
    const double simTime = std::chrono::duration<double>(t2 - t1).count();
    std::printf("ok: %s: %zu steps, t=[%g, %g], compile %.3f s, run %.3f s%s%s%s\n", path.c_str(),
                sim.takenSteps(), start, ended ? sim.time() : stop, init, simTime, csv.empty() ? "" : ", csv ",
                csv.c_str(), hashNote.c_str());
    return 0;
}

} // namespace tlmhub::cli
