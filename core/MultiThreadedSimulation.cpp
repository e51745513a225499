// Multi-core simulation of one model (core.md §10): the root's C and Q lists are split over
// threads, with a full barrier between the S, C and Q phases of every step, so results are
// identical to the single-threaded loop. S components (whose order matters) and logging run
// on the calling thread.
#include "core/System.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <numeric>
#include <thread>

namespace tlmhub {

namespace {

// Sense-reversing barrier: spins briefly, then yields (threads may outnumber cores).
class SpinBarrier {
public:
    explicit SpinBarrier(unsigned count) : mCount(count), mWaiting(0), mGeneration(0) {}

    void arriveAndWait()
    {
        const unsigned generation = mGeneration.load(std::memory_order_acquire);
        if (mWaiting.fetch_add(1, std::memory_order_acq_rel) + 1 == mCount) {
            mWaiting.store(0, std::memory_order_relaxed);
            mGeneration.fetch_add(1, std::memory_order_acq_rel);
            return;
        }
        for (unsigned spins = 0; mGeneration.load(std::memory_order_acquire) == generation; ++spins)
            if (spins > 200) std::this_thread::yield();
    }

private:
    const unsigned mCount;
    std::atomic<unsigned> mWaiting;
    std::atomic<unsigned> mGeneration;
};

std::size_t roundSteps(double x)
{
    if (!(x > 0.0)) return 0;
    return static_cast<std::size_t>(x + 0.5);
}

// Greedy partition by measured cost: most expensive first, onto the least loaded thread;
// each thread keeps its components in list order.
std::vector<std::vector<Component*>> partition(const std::vector<Component*>& list,
                                               const std::vector<double>& cost, unsigned threads)
{
    std::vector<std::size_t> order(list.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return cost[a] > cost[b]; });
    std::vector<double> load(threads, 0.0);
    std::vector<std::vector<std::size_t>> picks(threads);
    for (std::size_t i : order) {
        const auto t = static_cast<std::size_t>(std::min_element(load.begin(), load.end()) - load.begin());
        load[t] += cost[i];
        picks[t].push_back(i);
    }
    std::vector<std::vector<Component*>> out(threads);
    for (unsigned t = 0; t < threads; ++t) {
        std::sort(picks[t].begin(), picks[t].end());
        for (std::size_t i : picks[t]) out[t].push_back(list[i]);
    }
    return out;
}

} // namespace

bool System::simulateMultiThreaded(double tStop, unsigned threads)
{
    if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
    const std::size_t n = roundSteps(std::max(tStop - mTime, 0.0) / mTimestep);
    if (threads == 1 || n == 0) return simulate(tStop);

    // Measure each C and Q component's cost over the first steps (real steps of the run).
    const std::size_t probeSteps = std::min<std::size_t>(100, n);
    std::vector<double> costC(mC.size(), 0.0), costQ(mQ.size(), 0.0);
    using Clock = std::chrono::steady_clock;
    for (std::size_t step = 0; step < probeSteps; ++step) {
        if (mStopRequested) return false;
        mTime += mTimestep;
        const double t = mTime;
        for (Component* c : mS) runComponent(c, t);
        for (std::size_t i = 0; i < mC.size(); ++i) {
            const auto a = Clock::now();
            runComponent(mC[i], t);
            costC[i] += std::chrono::duration<double>(Clock::now() - a).count();
        }
        for (std::size_t i = 0; i < mQ.size(); ++i) {
            const auto a = Clock::now();
            runComponent(mQ[i], t);
            costQ[i] += std::chrono::duration<double>(Clock::now() - a).count();
        }
        ++mTakenSteps;
        logSample();
    }
    const auto partC = partition(mC, costC, threads);
    const auto partQ = partition(mQ, costQ, threads);

    SpinBarrier barrier(threads);
    std::atomic<bool> abort{false};
    const std::size_t remaining = n - probeSteps;
    auto worker = [&](unsigned id) {
        for (std::size_t step = 0; step < remaining; ++step) {
            barrier.arriveAndWait();   // S phase done (master)
            if (abort.load(std::memory_order_acquire)) return;
            const double t = mTime;
            for (Component* c : partC[id]) runComponent(c, t);
            barrier.arriveAndWait();   // C phase done
            for (Component* c : partQ[id]) runComponent(c, t);
            barrier.arriveAndWait();   // Q phase done
        }
    };
    std::vector<std::thread> pool;
    for (unsigned id = 1; id < threads; ++id) pool.emplace_back(worker, id);
    for (std::size_t step = 0; step < remaining; ++step) {
        if (mStopRequested) {
            abort.store(true, std::memory_order_release);
            barrier.arriveAndWait();
            break;
        }
        mTime += mTimestep;
        const double t = mTime;
        for (Component* c : mS) runComponent(c, t);
        barrier.arriveAndWait();
        for (Component* c : partC[0]) runComponent(c, t);
        barrier.arriveAndWait();
        for (Component* c : partQ[0]) runComponent(c, t);
        barrier.arriveAndWait();
        ++mTakenSteps;
        logSample();
        if (mProgress && mProgressInterval && (probeSteps + step + 1) % mProgressInterval == 0)
            mProgress(mProgressUser, probeSteps + step + 1, n);
    }
    for (auto& th : pool) th.join();
    return !mStopRequested;
}

} // namespace tlmhub
