#include "cli/Commands.h"
#include "cli/Options.h"

#include "core/ResultTable.h"
#include "core/Results.h"
#include "core/Sha256.h"
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
    LoadedModel model = loadHmfFile(path);
    if (model.hasErrors()) {
        std::cerr << "error: " << model.firstError() << "\n";
        return 1;
    }
    System& root = *model.root;
    double start = root.startTime, stop = root.stopTime;
    std::string err;
    if (!opt.number("start", start, err) || !opt.number("stop", stop, err) ||
        !opt.number("step", root.desiredTimestep, err)) {
        std::cerr << "error: " << err << "\n";
        return 2;
    }
    double samples = static_cast<double>(root.requestedLogSamples);
    if (!opt.number("samples", samples, err)) {
        std::cerr << "error: " << err << "\n";
        return 2;
    }
    root.requestedLogSamples = static_cast<std::size_t>(samples);
    const std::string csv = opt.value("csv");
    const bool wantsHash = opt.has("sha256");
    if ((!csv.empty() || wantsHash) && root.requestedLogSamples == 0) root.requestedLogSamples = 1024;
    if (!(stop >= start) || !(root.desiredTimestep > 0.0)) {
        std::cerr << "error: need stop >= start and a positive time step\n";
        return 2;
    }

    const auto t0 = std::chrono::steady_clock::now();
    if (!root.checkModel(err)) {
        std::cerr << "error: " << path << ": " << err << "\n";
        return 1;
    }
    bool ok = root.initialize(start, stop);
    const auto t1 = std::chrono::steady_clock::now();
    double threads = 1;
    if (!opt.number("threads", threads, err) || threads < 0) {
        std::cerr << "error: --threads needs a count >= 0\n";
        return 2;
    }
    if (ok) ok = root.simulateMultiThreaded(stop, static_cast<unsigned>(threads));
    const auto t2 = std::chrono::steady_clock::now();
    root.finalize();
    for (const auto& m : root.messages())
        if (m.type == MessageType::Error || m.type == MessageType::Fatal)
            std::cerr << "error: " << m.text << "\n";
    if (!ok) {
        std::fprintf(stderr, "error: %s: simulation stopped at t=%g before the stop time %g\n",
                     path.c_str(), root.time(), stop);
        return 1;
    }
    std::string where;
    if (opt.has("check-finite") && findNonFinite(root, where)) {
        std::cerr << "error: " << path << ": non-finite value: " << where << "\n";
        return 1;
    }
    std::string hashNote;
    if (!csv.empty() || wantsHash) {
        const ResultTable table = ResultTable::fromSystem(root);
        if (!csv.empty() && !writeCsv(table, csv, err)) {
            std::cerr << "error: " << err << "\n";
            return 1;
        }
        if (wantsHash) hashNote = ", csv sha256 " + csvSha256(table);
    }
    const double init = std::chrono::duration<double>(t1 - t0).count();
    const double sim = std::chrono::duration<double>(t2 - t1).count();
    std::printf("ok: %s: %zu steps, t=[%g, %g], init %.3f s, simulation %.3f s%s%s%s\n", path.c_str(),
                root.takenSteps(), start, stop, init, sim, csv.empty() ? "" : ", csv ",
                csv.c_str(), hashNote.c_str());
    return 0;
}

} // namespace tlmhub::cli
