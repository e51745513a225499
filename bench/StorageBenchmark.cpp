// Google Benchmark of the storage work of one job, on each back end: create it, mark it
// running, report progress twice, finish it with Position Servo's stored result (encodeResult,
// about 0.5 MB), then read the result back as the client does. Back ends:
//   sqlite       the server's default (WAL, flushed at checkpoints)
//   sqlite_full  SQLite flushing the WAL at every commit (synchronous=FULL)
//   postgresql   a PostgreSQL 15 the benchmark starts on loopback, with fsync and synchronous
//                commit on (Debian's postgresql-15 must be installed)
// All files live in the temporary directory, so the disk under /tmp is what is measured.
#include "core/Simulation.h"
#include "core/hmf/HmfLoader.h"
#include "server/store/ResultBlob.h"
#include "server/store/Storage.h"
#include "TemporaryDirectory.h"
#include "TemporaryPostgres.h"

#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>

using namespace tlmhub;
using namespace tlmhub::server;

namespace {

std::string servoResultBlob()
{
    std::ifstream in(std::string(TLMHUB_SHARED_DIR) + "/hopsan-models/Example Models/Position Servo.hmf");
    std::stringstream text;
    text << in.rdbuf();
    LoadedModel model = loadHmfString(text.str(), "", "servo");
    if (model.hasErrors()) throw std::runtime_error(model.firstError());
    Result<Simulation> sim = compile(*model.root, {});
    if (!sim) throw std::runtime_error(sim.status().message());
    if (const Status ran = sim->run(); !ran) throw std::runtime_error(ran.message());
    return encodeResult(sim->results());
}

class TemporaryDir {
public:
    TemporaryDir() : mPath(test::makeTemporaryDirectory("tlmhub-bench-")) {}
    ~TemporaryDir() { std::filesystem::remove_all(mPath); }
    const std::filesystem::path& path() const { return mPath; }

private:
    std::filesystem::path mPath;
};

enum Backend { Sqlite, SqliteFull, Postgres };

void BM_JobStorage(benchmark::State& state, Backend backend)
{
    const std::string blob = servoResultBlob();
    TemporaryDir dir;
    std::unique_ptr<test::TemporaryPostgres> postgres;
    StorageConfig config{.database = (dir.path() / "tlmhub.sqlite").string(), .reserveBytes = 0,
                         .syncEveryCommit = backend == SqliteFull};
    if (backend == Postgres) {
        postgres = std::make_unique<test::TemporaryPostgres>("tlmhub_bench", true);
        config.database = postgres->uri();
    }
    const auto storage = openStorage(config);
    JobRequest request;
    request.ownerId = 1;
    JobInfo resolved;
    resolved.steps = 10000;
    for (auto _ : state) {
        const std::int64_t id = storage->jobs().create(request, resolved);
        storage->jobs().markRunning(id);
        storage->jobs().setProgress(id, 0.3);
        storage->jobs().setProgress(id, 0.6);
        storage->jobs().finish(id, JobState::Done, "", resolved.steps, &blob);
        benchmark::DoNotOptimize(storage->results().blob(id));
    }
    state.counters["result_bytes"] = static_cast<double>(blob.size());
    state.SetItemsProcessed(state.iterations());
}

} // namespace

BENCHMARK_CAPTURE(BM_JobStorage, sqlite, Sqlite)->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK_CAPTURE(BM_JobStorage, sqlite_full, SqliteFull)->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK_CAPTURE(BM_JobStorage, postgresql, Postgres)->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK_MAIN();
