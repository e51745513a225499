// What it costs to get from a model to a compiled simulation: loading the .hmf text, saving
// it, copying the in-memory model (what compile(const Model&) does), and compiling.
#include "core/Model.h"
#include "core/Simulation.h"
#include "core/hmf/HmfLoader.h"

#include <benchmark/benchmark.h>

#include <filesystem>
#include <string>

using namespace tlmhub;

namespace {

std::string modelPath(const char* file)
{
    return std::string(TLMHUB_SHARED_DIR) + "/" + file;
}

// The model, or null (and the benchmark marked failed) if it does not load.
std::unique_ptr<Model> load(benchmark::State& state, const char* file)
{
    LoadedModel loaded = loadHmfFile(modelPath(file));
    if (!loaded.root) {
        state.SkipWithError(("cannot load " + modelPath(file)).c_str());
        return nullptr;
    }
    return std::make_unique<Model>(std::move(loaded.root));
}

void BM_LoadHmfText(benchmark::State& state, const char* file)
{
    const std::unique_ptr<Model> model = load(state, file);
    if (!model) return;
    const std::string text = model->toHmf();
    for (auto _ : state) benchmark::DoNotOptimize(loadHmfString(text, model->root().modelDirectory));
}

void BM_SaveHmfText(benchmark::State& state, const char* file)
{
    const std::unique_ptr<Model> model = load(state, file);
    if (!model) return;
    for (auto _ : state) benchmark::DoNotOptimize(model->toHmf());
}

void BM_CopyModel(benchmark::State& state, const char* file)
{
    const std::unique_ptr<Model> model = load(state, file);
    if (!model) return;
    for (auto _ : state) benchmark::DoNotOptimize(model->copy());
}

// A copy, its structure checked and every parameter evaluated.
void BM_CompileModel(benchmark::State& state, const char* file)
{
    const std::unique_ptr<Model> model = load(state, file);
    if (!model) return;
    for (auto _ : state) benchmark::DoNotOptimize(compile(*model));
}

#define TLMHUB_MODEL_BENCHMARKS(fn)                                                                  \
    BENCHMARK_CAPTURE(fn, PositionServo, "hopsan-models/Example Models/Position Servo.hmf")          \
        ->Unit(benchmark::kMicrosecond);                                                             \
    BENCHMARK_CAPTURE(fn, x200, "bench-models/position-servo-x200.hmf")->Unit(benchmark::kMillisecond)

TLMHUB_MODEL_BENCHMARKS(BM_LoadHmfText);
TLMHUB_MODEL_BENCHMARKS(BM_SaveHmfText);
TLMHUB_MODEL_BENCHMARKS(BM_CopyModel);
TLMHUB_MODEL_BENCHMARKS(BM_CompileModel);

} // namespace

BENCHMARK_MAIN();
