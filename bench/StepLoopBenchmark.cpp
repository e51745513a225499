// Google Benchmark of the step loop: a chain of representative C and Q components, and a
// whole bench model. Figures are per simulated step; compare configurations in one run.
#include "core/ComponentFactory.h"
#include "core/System.h"
#include "core/hmf/HmfLoader.h"

#include <benchmark/benchmark.h>

#include <filesystem>
#include <memory>
#include <string>

using namespace tlmhub;

namespace {

std::string add(System& s, const std::string& type, const std::string& name)
{
    auto c = ComponentFactory::instance().create(type);
    c->setNameRaw(name);
    return s.addComponent(std::move(c));
}

// pressure source -> (orifice -> volume) x n -> orifice -> tank
std::unique_ptr<System> hydraulicChain(int n)
{
    auto s = std::make_unique<System>();
    add(*s, "HydraulicPressureSourceC", "Source");
    std::string prev = "Source";
    std::string prevPort = "P1";
    for (int i = 0; i < n; ++i) {
        const std::string o = add(*s, "HydraulicLaminarOrifice", "O" + std::to_string(i));
        const std::string v = add(*s, "HydraulicVolume", "V" + std::to_string(i));
        s->connect(prev, prevPort, o, "P1");
        s->connect(o, "P2", v, "P1");
        prev = v;
        prevPort = "P2";
    }
    const std::string o = add(*s, "HydraulicLaminarOrifice", "Out");
    add(*s, "HydraulicTankC", "Tank");
    s->connect(prev, prevPort, o, "P1");
    s->connect(o, "P2", "Tank", "P1");
    return s;
}

void BM_HydraulicChainStep(benchmark::State& state)
{
    auto s = hydraulicChain(static_cast<int>(state.range(0)));
    s->desiredTimestep = 1e-4;
    s->requestedLogSamples = 0;
    s->initialize(0.0, 1e9);
    double t = 0.0;
    for (auto _ : state) {
        t += 1e-4;
        s->simulate(t);
    }
    s->finalize();
    state.counters["components"] = static_cast<double>(2 * state.range(0) + 3);
    state.SetItemsProcessed(state.iterations() * (2 * state.range(0) + 3));
}
BENCHMARK(BM_HydraulicChainStep)->Arg(10)->Arg(100)->Arg(1000);

void BM_BenchModel(benchmark::State& state, const char* file, unsigned threads)
{
    const std::string path = std::string(TLMHUB_SHARED_DIR) + "/bench-models/" + file;
    if (!std::filesystem::exists(path)) {
        state.SkipWithError("bench model not found");
        return;
    }
    LoadedModel m = loadHmfFile(path);
    System& root = *m.root;
    for (auto _ : state) {
        root.initialize(0.0, 0.1);
        root.simulateMultiThreaded(0.1, threads);
        root.finalize();
    }
}
BENCHMARK_CAPTURE(BM_BenchModel, x50_1thread, "position-servo-x50.hmf", 1u)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_BenchModel, x50_2threads, "position-servo-x50.hmf", 2u)->Unit(benchmark::kMillisecond);

} // namespace

BENCHMARK_MAIN();
