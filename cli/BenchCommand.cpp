#include "cli/Commands.h"
#include "cli/Options.h"

#include "core/hmf/HmfLoader.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>

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

} // namespace

int benchCommand(const std::vector<std::string>& args)
{
    Options opt(args);
    if (opt.positional.size() != 1) {
        std::cerr << "tlmhub-cli bench: expected one model file\n";
        return 2;
    }
    double repeat = 5, threads = 1;
    std::string err;
    if (!opt.number("repeat", repeat, err) || !opt.number("threads", threads, err)) {
        std::cerr << "error: " << err << "\n";
        return 2;
    }
    const auto l0 = std::chrono::steady_clock::now();
    LoadedModel model = loadHmfFile(opt.positional[0]);
    if (model.hasErrors()) {
        std::cerr << "error: " << model.firstError() << "\n";
        return 1;
    }
    const auto l1 = std::chrono::steady_clock::now();
    System& root = *model.root;
    std::vector<double> times;
    std::size_t steps = 0;
    for (int k = 0; k < static_cast<int>(repeat); ++k) {
        if (!root.checkModel(err) || !root.initialize(root.startTime, root.stopTime)) {
            std::cerr << "error: initialisation failed: " << err << "\n";
            return 1;
        }
        const auto s0 = std::chrono::steady_clock::now();
        const bool ok = root.simulateMultiThreaded(root.stopTime, static_cast<unsigned>(threads));
        const auto s1 = std::chrono::steady_clock::now();
        root.finalize();
        if (!ok) {
            std::cerr << "error: simulation failed\n";
            return 1;
        }
        steps = root.takenSteps();
        times.push_back(std::chrono::duration<double>(s1 - s0).count());
    }
    std::sort(times.begin(), times.end());
    const double median = times[times.size() / 2];
    const std::size_t comps = root.countComponents();
    std::printf("model %s: %zu components, %zu steps, load %.3f s\n", opt.positional[0].c_str(), comps,
                steps, std::chrono::duration<double>(l1 - l0).count());
    std::printf("simulation min %.4f s, median %.4f s, max %.4f s (%zu runs, %g thread(s))\n",
                times.front(), median, times.back(), times.size(), threads);
    std::printf("%.0f steps/s, %.2f ns per component-step, peak RSS %ld KiB\n", steps / median,
                median * 1e9 / (static_cast<double>(steps) * static_cast<double>(comps)), peakRssKiB());
    return 0;
}

} // namespace tlmhub::cli
