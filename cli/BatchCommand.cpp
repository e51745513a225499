#include "cli/Commands.h"
#include "cli/Options.h"

#include "core/Simulation.h"
#include "core/hmf/HmfLoader.h"

#include <atomic>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <thread>
#include <vector>

namespace tlmhub::cli {

// Many independent models at once (a class of students): each model runs single-threaded,
// the models are spread over a pool of worker threads.
int batchCommand(const std::vector<std::string>& args)
{
    Options opt(args);
    if (opt.positional.empty()) {
        std::cerr << "tlmhub-cli batch: expected one or more model files\n";
        return 2;
    }
    double threads = 0, copies = 1;
    std::string err;
    if (!opt.number("threads", threads, err) || !opt.number("copies", copies, err) || copies < 1) {
        std::cerr << "error: " << (err.empty() ? "--copies must be >= 1" : err) << "\n";
        return 2;
    }
    unsigned nThreads = threads > 0 ? static_cast<unsigned>(threads) : std::max(1u, std::thread::hardware_concurrency());

    // Each file is loaded once; the copies are copies of its Model.
    std::vector<Model> models;
    for (const std::string& path : opt.positional) {
        LoadedModel m = loadHmfFile(path);
        if (m.hasErrors()) {
            std::cerr << "error: " << m.firstError() << "\n";
            return 1;
        }
        models.emplace_back(std::move(m.root));
    }
    const std::size_t files = models.size();
    for (int k = 1; k < static_cast<int>(copies); ++k)
        for (std::size_t i = 0; i < files; ++i) {
            Result<Model> copy = models[i].copy();
            if (!copy) {
                std::cerr << "error: " << opt.positional[i] << ": " << describe(copy.status()) << "\n";
                return 1;
            }
            models.push_back(std::move(*copy));
        }
    std::atomic<std::size_t> next{0};
    std::atomic<std::size_t> failed{0};
    std::atomic<std::size_t> componentSteps{0};
    auto worker = [&]() {
        for (std::size_t i; (i = next.fetch_add(1)) < models.size();) {
            const std::size_t components = models[i].root().countComponents();
            Result<Simulation> sim = compile(std::move(models[i]));
            if (!sim || !sim->run()) {
                ++failed;
                continue;
            }
            componentSteps += sim->takenSteps() * components;
        }
    };
    const auto t0 = std::chrono::steady_clock::now();
    std::vector<std::thread> pool;
    for (unsigned t = 0; t < nThreads; ++t) pool.emplace_back(worker);
    for (auto& th : pool) th.join();
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("%zu models on %u threads: %.3f s, %.1f models/s, %.3g component-steps/s, %zu failed\n",
                models.size(), nThreads, wall, models.size() / wall, componentSteps.load() / wall,
                failed.load());
    return failed == 0 ? 0 : 1;
}

} // namespace tlmhub::cli
