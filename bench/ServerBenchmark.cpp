// Google Benchmark of the server's per-job work besides the simulation, on Position Servo
// (2048 samples of 128 variables): storing its result (the stored form against the
// uncompressed table it replaced, in one run), reading it back, and encoding stream frames of
// 16 and of 2 variables as JSON text and as binary messages.
#include "core/ResultTable.h"
#include "core/Simulation.h"
#include "core/hmf/HmfLoader.h"
#include "server/jobs/StreamFrame.h"
#include "server/store/ResultBlob.h"

#include <benchmark/benchmark.h>

#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>

using namespace tlmhub;
using namespace tlmhub::server;

namespace {

struct ServoRun {
    ServoRun()
    {
        std::ifstream in(std::string(TLMHUB_SHARED_DIR) + "/hopsan-models/Example Models/Position Servo.hmf");
        std::stringstream text;
        text << in.rdbuf();
        model = loadHmfString(text.str(), "", "servo");
        if (model.hasErrors()) throw std::runtime_error(model.firstError());
        Result<Simulation> compiled = compile(*model.root, {});
        if (!compiled) throw std::runtime_error(compiled.status().message());
        sim.emplace(std::move(*compiled));
        if (const Status ran = sim->run(); !ran) throw std::runtime_error(ran.message());
    }
    LoadedModel model;
    std::optional<Simulation> sim;
};

ServoRun& servo()
{
    static ServoRun run;
    return run;
}

void BM_StoreResultCompressed(benchmark::State& state)
{
    const ResultView view = servo().sim->results();
    std::size_t bytes = 0;
    for (auto _ : state) bytes = encodeResult(view).size();
    state.counters["stored_bytes"] = static_cast<double>(bytes);
}

// What a job did before: copy the log into a ResultTable, then serialize it.
void BM_StoreResultAsTable(benchmark::State& state)
{
    const ResultView view = servo().sim->results();
    std::size_t bytes = 0;
    for (auto _ : state) bytes = ResultTable::fromView(view).serialize().size();
    state.counters["stored_bytes"] = static_cast<double>(bytes);
}

void BM_ReadResultAll(benchmark::State& state)
{
    const std::string blob = encodeResult(servo().sim->results());
    for (auto _ : state) benchmark::DoNotOptimize(decodeResult(blob));
}

void BM_ReadResultOneVariable(benchmark::State& state)
{
    const ResultView view = servo().sim->results();
    const std::string blob = encodeResult(view);
    const std::vector<std::string> one{view.variable(view.numVariables() / 2).fullName};
    for (auto _ : state) benchmark::DoNotOptimize(decodeResult(blob, one));
}

// One frame of `range(0)` variables with 68 samples each (a 30 Hz frame of a run that logs
// 2048 samples a second), encoded for a fresh subscriber each time.
StreamFrame servoFrame(std::size_t variables)
{
    const ResultView view = servo().sim->results();
    std::vector<std::string> names;
    auto samples = std::make_shared<FrameSamples>();
    const auto time = view.time();
    samples->time.assign(time.begin(), time.begin() + 68);
    for (std::size_t i = 0; i < variables; ++i) {
        names.push_back(view.variable(i).fullName);
        const auto data = view.data(i);
        samples->columns.emplace_back(data.begin(), data.begin() + 68);
    }
    StreamFrame frame;
    frame.jobId = 1;
    frame.layout = std::make_shared<FrameLayout>(std::move(names));
    frame.parts.push_back(samples);
    return frame;
}

// A new publication with the frame's samples: its JSON text is not cached yet.
void republish(StreamFrame& frame)
{
    auto copy = std::make_shared<FrameSamples>();
    copy->time = frame.parts[0]->time;
    copy->columns = frame.parts[0]->columns;
    frame.parts[0] = std::move(copy);
}

void BM_FrameJson(benchmark::State& state)
{
    StreamFrame frame = servoFrame(static_cast<std::size_t>(state.range(0)));
    for (auto _ : state) {
        republish(frame);
        benchmark::DoNotOptimize(frame.jsonText(0));
    }
}

void BM_FrameBinary(benchmark::State& state)
{
    StreamFrame frame = servoFrame(static_cast<std::size_t>(state.range(0)));
    for (auto _ : state) {
        republish(frame);
        benchmark::DoNotOptimize(frame.binaryMessage(0));
    }
}

} // namespace

BENCHMARK(BM_StoreResultCompressed)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StoreResultAsTable)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReadResultAll)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReadResultOneVariable)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_FrameJson)->Arg(2)->Arg(16)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_FrameBinary)->Arg(2)->Arg(16)->Unit(benchmark::kMicrosecond);
BENCHMARK_MAIN();
