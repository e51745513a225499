#include "cli/Commands.h"
#include "cli/Options.h"
#include "cli/ThreadCount.h"

#include "core/Simulation.h"
#include "core/hmf/HmfLoader.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <thread>

namespace tlmhub::cli {

namespace {

long peakRssKiB()
{
    std::ifstream in("/proc/self/status");
    std::string line;
    while (std::getline(in, line))
        if (line.rfind("VmHWM:", 0) == 0) return std::strtol(line.c_str() + 6, nullptr, 10);
    return -1;
}

// "--threads 1,2,auto" -> {1, 2, autoThreads}.
bool parseThreadList(const std::string& text, std::vector<unsigned>& out, std::string& error)
{
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, ',')) {
        const std::optional<unsigned> threads = parseThreadCount(item);
        if (!threads) {
            error = "--threads needs counts or auto, such as 2 or 1,2,auto; got '" + text + "'";
            return false;
        }
        out.push_back(*threads);
    }
    if (out.empty()) out.push_back(1);
    return true;
}

double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

// "Comp.param=a:b:n" -> the path and n values evenly from a to b.
bool parseVary(const std::string& text, std::string& path, std::vector<double>& values, std::string& error)
{
    const std::size_t eq = text.find('=');
    double a = 0, b = 0;
    int n = 0;
    char tail = 0;
    if (eq == std::string::npos ||
        std::sscanf(text.c_str() + eq + 1, "%lf:%lf:%d%c", &a, &b, &n, &tail) != 3 || n < 1) {
        error = "--vary needs Comp.param=a:b:n, got '" + text + "'";
        return false;
    }
    path = text.substr(0, eq);
    for (int i = 0; i < n; ++i) values.push_back(n == 1 ? a : a + (b - a) * i / (n - 1));
    return true;
}

// Runs of one model with one parameter changed between them, four ways: setParameter +
// reset + run on one Simulation, reset + run without a change, compile (a copy of the loaded
// Model) + run, and load + compile + run.
int benchVary(const std::string& modelPath, const std::string& vary)
{
    std::string path, err;
    std::vector<double> values;
    if (!parseVary(vary, path, values, err)) {
        std::cerr << "error: " << err << "\n";
        return 2;
    }
    using Clock = std::chrono::steady_clock;
    LoadedModel loaded = loadHmfFile(modelPath);
    if (loaded.hasErrors()) {
        std::cerr << "error: " << loaded.firstError() << "\n";
        return 1;
    }
    const Model model(std::move(loaded.root));
    Result<Simulation> sim = compile(model);
    if (!sim) {
        std::cerr << "error: " << describe(sim.status()) << "\n";
        return 1;
    }
    auto fail = [](const Status& s) {
        std::cerr << "error: " << describe(s) << "\n";
        return 1;
    };
    // The ways alternate run by run, so machine drift hits them alike.
    double varied = 0, same = 0, copied = 0, reloaded = 0;
    auto seconds = [](Clock::time_point from) {
        return std::chrono::duration<double>(Clock::now() - from).count();
    };
    for (double v : values) {
        auto t = Clock::now();
        Status s = sim->setParameter(path, formatNumber(v));
        if (s) s = sim->reset();
        if (s) s = sim->run();
        if (!s) return fail(s);
        varied += seconds(t);

        t = Clock::now();
        s = sim->reset();
        if (s) s = sim->run();
        if (!s) return fail(s);
        same += seconds(t);

        t = Clock::now();
        Result<Simulation> copy = compile(model);
        if (!copy) return fail(copy.status());
        s = copy->setParameter(path, formatNumber(v));
        if (s) s = copy->run();
        if (!s) return fail(s);
        copied += seconds(t);

        t = Clock::now();
        LoadedModel fresh = loadHmfFile(modelPath);
        Result<Simulation> again = compile(*fresh.root);
        if (!again) return fail(again.status());
        s = again->setParameter(path, formatNumber(v));
        if (s) s = again->run();
        if (!s) return fail(s);
        reloaded += seconds(t);
    }
    const double n = static_cast<double>(values.size());
    std::printf("%zu runs of %s varying %s\n", values.size(), modelPath.c_str(), path.c_str());
    std::printf("setParameter + reset + run: %.4f s (%.5f s per run)\n", varied, varied / n);
    std::printf("reset + run:                %.4f s (%.5f s per run), varied/same %.3fx\n", same, same / n,
                varied / same);
    std::printf("compile a copy + run:       %.4f s (%.5f s per run), copy/varied %.3fx\n", copied,
                copied / n, copied / varied);
    std::printf("load + compile + run:       %.4f s (%.5f s per run), reload/varied %.3fx\n", reloaded,
                reloaded / n, reloaded / varied);
    return 0;
}

} // namespace

// Loads once, then simulates `repeat` rounds. With several thread counts each round runs
// every count back to back, so a speed-up is a ratio of runs made under the same machine
// conditions (shared VMs drift by tens of percent within minutes).
int benchCommand(const std::vector<std::string>& args)
{
    Options opt(args);
    if (opt.positional.size() != 1) {
        std::cerr << "tlmhub-cli bench: expected one model file\n";
        return 2;
    }
    double repeat = 5;
    std::vector<unsigned> threadCounts;
    std::string err;
    if (!opt.number("repeat", repeat, err) || !parseThreadList(opt.has("threads") ? opt.value("threads") : "1",
                                                                 threadCounts, err)) {
        std::cerr << "error: " << err << "\n";
        return 2;
    }
    if (repeat < 1) repeat = 1;
    if (opt.has("vary")) return benchVary(opt.positional[0], opt.value("vary"));
    const auto l0 = std::chrono::steady_clock::now();
    LoadedModel model = loadHmfFile(opt.positional[0]);
    if (model.hasErrors()) {
        std::cerr << "error: " << model.firstError() << "\n";
        return 1;
    }
    const auto l1 = std::chrono::steady_clock::now();
    System& root = *model.root;
    Result<Simulation> compiled = compile(root);
    if (!compiled) {
        std::cerr << "error: " << describe(compiled.status()) << "\n";
        return 1;
    }
    Simulation& sim = *compiled;
    std::vector<std::vector<double>> times(threadCounts.size());
    std::vector<unsigned> threadsUsed(threadCounts.size(), 1);
    for (int k = 0; k < static_cast<int>(repeat); ++k) {
        for (std::size_t c = 0; c < threadCounts.size(); ++c) {
            // Only the steps are timed: reset and initialisation happen before the clock starts.
            Status status = sim.reset();
            if (status) status = sim.initialise();
            if (!status) {
                std::cerr << "error: initialisation failed: " << describe(status) << "\n";
                return 1;
            }
            const auto s0 = std::chrono::steady_clock::now();
            status = sim.run({.threads = threadCounts[c]});
            const auto s1 = std::chrono::steady_clock::now();
            if (!status) {
                std::cerr << "error: simulation failed: " << describe(status) << "\n";
                return 1;
            }
            times[c].push_back(std::chrono::duration<double>(s1 - s0).count());
            threadsUsed[c] = sim.threadsUsed();
        }
    }
    const std::size_t steps = sim.totalSteps();
    const std::size_t comps = root.countComponents();
    std::printf("model %s: %zu components, %zu steps, load %.3f s\n", opt.positional[0].c_str(), comps,
                steps, std::chrono::duration<double>(l1 - l0).count());
    for (std::size_t c = 0; c < threadCounts.size(); ++c) {
        const auto [lo, hi] = std::minmax_element(times[c].begin(), times[c].end());
        const double med = median(times[c]);
        const std::string used = threadCounts[c] == RunOptions::autoThreads
                                     ? " (last run ended on " + std::to_string(threadsUsed[c]) + ")"
                                     : "";
        std::printf("simulation min %.4f s, median %.4f s, max %.4f s (%zu runs, %s thread(s)%s)\n", *lo, med, *hi,
                    times[c].size(), threadCountName(threadCounts[c]).c_str(), used.c_str());
        std::printf("%.0f steps/s, %.2f ns per component-step\n", steps / med,
                    med * 1e9 / (static_cast<double>(steps) * static_cast<double>(comps)));
    }
    for (std::size_t c = 1; c < threadCounts.size(); ++c) {
        std::vector<double> ratios;
        for (std::size_t k = 0; k < times[c].size(); ++k) ratios.push_back(times[0][k] / times[c][k]);
        const auto [lo, hi] = std::minmax_element(ratios.begin(), ratios.end());
        std::printf("speed-up %s vs %s thread(s): median %.2fx (per round %.2fx to %.2fx)\n",
                    threadCountName(threadCounts[c]).c_str(), threadCountName(threadCounts[0]).c_str(), median(ratios),
                    *lo, *hi);
    }
    std::printf("peak RSS %ld KiB\n", peakRssKiB());
    return 0;
}

} // namespace tlmhub::cli
