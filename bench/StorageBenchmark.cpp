// Google Benchmark of the storage work of one job, on each back end: create it, mark it
// running, report progress twice, finish it with Position Servo's stored result (encodeResult,
// about 0.5 MB), then read the result back as the client does. Back ends:
//   sqlite       the server's default (WAL, flushed at checkpoints)
//   sqlite_full  SQLite flushing the WAL at every commit (synchronous=FULL)
//   postgresql   a PostgreSQL 15 the benchmark starts on loopback, with fsync and synchronous
//                commit on (Debian's postgresql-15 must be installed)
// All files live in the temporary directory, so the disk under /tmp is what is measured.
// BM_JobLease: the job queue's own work per job on each back end (claim, one lease renewal,
// finishLeased), as a worker node of a scale-out deployment does it.
#include "core/Simulation.h"
#include "core/hmf/HmfLoader.h"
#include "server/store/ResultBlob.h"
#include "server/store/Storage.h"
#include "TemporaryDirectory.h"
#include "TemporaryPostgres.h"

#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <vector>

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

// A fresh database of the back end: an SQLite file in `dir`, or a durable PostgreSQL that
// `postgres` keeps running.
std::unique_ptr<Storage> openBenchStorage(Backend backend, const TemporaryDir& dir,
                                          std::unique_ptr<test::TemporaryPostgres>& postgres)
{
    StorageConfig config{.database = (dir.path() / "tlmhub.sqlite").string(), .reserveBytes = 0,
                         .syncEveryCommit = backend == SqliteFull};
    if (backend == Postgres) {
        postgres = std::make_unique<test::TemporaryPostgres>("tlmhub_bench", true);
        config.database = postgres->uri();
    }
    return openStorage(config);
}


void BM_JobStorage(benchmark::State& state, Backend backend)
{
    const std::string blob = servoResultBlob();
    TemporaryDir dir;
    std::unique_ptr<test::TemporaryPostgres> postgres;
    const auto storage = openBenchStorage(backend, dir, postgres);
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

// The job queue's own work per job on a back end (server/store/JobLeaseStore.h), as a worker
// node does it: claim the job (one queued), renew its lease once (a heartbeat; a job of up to
// a third of the lease needs none, a longer one one per lease/3) and store its end with the
// lease number, without a result (the result's cost is BM_JobStorage's). Creating the job is
// not timed.
void BM_JobLease(benchmark::State& state, Backend backend)
{
    TemporaryDir dir;
    std::unique_ptr<test::TemporaryPostgres> postgres;
    const auto storage = openBenchStorage(backend, dir, postgres);
    const auto owner = storage->users().insert("bench", "", "user");
    if (!owner) throw std::runtime_error("cannot create the benchmark's user");
    JobRequest request;
    request.ownerId = owner->id;
    JobInfo resolved;
    resolved.steps = 10000;
    JobLeaseStore& leases = storage->jobLeases();
    const ClaimRequest claim{.nodeId = "bench-node", .count = 1, .maxRunningPerUser = 2,
                             .leaseTime = std::chrono::milliseconds(10'000)};
    for (auto _ : state) {
        state.PauseTiming();
        storage->jobs().create(request, resolved);
        state.ResumeTiming();
        const std::vector<JobLease> claimed = leases.claim(claim);
        if (claimed.size() != 1) {
            state.SkipWithError("claim returned no job");
            break;
        }
        const auto lost = leases.renew(claim.nodeId, claimed, claim.leaseTime);
        if (!lost.empty() || !leases.finishLeased(claimed.front(), JobState::Done, "", resolved.steps, nullptr)) {
            state.SkipWithError("the lease was lost");
            break;
        }
    }
    state.SetItemsProcessed(state.iterations());
}

} // namespace

BENCHMARK_CAPTURE(BM_JobLease, sqlite, Sqlite)->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK_CAPTURE(BM_JobLease, sqlite_full, SqliteFull)->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK_CAPTURE(BM_JobLease, postgresql, Postgres)->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK_CAPTURE(BM_JobStorage, sqlite, Sqlite)->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK_CAPTURE(BM_JobStorage, sqlite_full, SqliteFull)->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK_CAPTURE(BM_JobStorage, postgresql, Postgres)->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK_MAIN();
