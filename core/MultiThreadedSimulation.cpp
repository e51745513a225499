// Multi-core simulation of one model (core.md §10): the root's S, C and Q lists are split
// over threads by region, with barriers between the phases of every step, so results are
// identical to the single-threaded loop. Clusters of components linked by a node go whole
// to one thread (their order matters); on log steps every thread copies its own share of
// the logged nodes.
#include "core/ComponentClusters.h"
#include "core/System.h"
#include "core/ThreadJudge.h"

#include <algorithm>
#include <atomic>
#include <limits>
#include <map>
#include <chrono>
#include <cmath>
#include <numeric>
#include <set>
#include <thread>

namespace tlmhub {

namespace {

// Automatic thread count (simulateStepsAutoThreaded; judged by ThreadJudge).
constexpr double kTimedWindowSeconds = 0.5e-3;     // a timed window lasts at least this
constexpr double kMinThreadedStepSeconds = 250e-9;  // cheaper steps stay on one thread
constexpr double kMinThreadedRunSeconds = 0.1;      // so do rests of a run too short to judge threads
constexpr unsigned kMaxAutoThreads = 8;

// Sense-reversing barrier. A phase lasts microseconds, so a waiting thread spins (a
// sched_yield per wait cost about 6 % of a 2-thread x200 run). A wait far longer than a
// phase means a thread of the group is descheduled (another process took its core, or
// there are more threads than cores): the waiting threads then sleep until the last one
// arrives, leaving their cores to it instead of spinning away its time slices. The last
// thread to arrive runs `onComplete` before anyone is released.
class SpinBarrier {
public:
    explicit SpinBarrier(unsigned count)
        : mCount(count), mWaiting(0), mGeneration(0),
          // About 50 us of spinning here; with more threads than cores a short spin.
          mSpinsBeforeSleep(count <= std::thread::hardware_concurrency() ? 1u << 17 : 2000u)
    {
    }

    template <typename OnComplete>
    void arriveAndWait(OnComplete onComplete)
    {
        const unsigned generation = mGeneration.load(std::memory_order_acquire);
        if (mWaiting.fetch_add(1, std::memory_order_acq_rel) + 1 == mCount) {
            onComplete();
            mWaiting.store(0, std::memory_order_relaxed);
            mGeneration.fetch_add(1, std::memory_order_acq_rel);
            mGeneration.notify_all();   // a system call only when some thread sleeps
            return;
        }
        for (unsigned spins = 0; spins < mSpinsBeforeSleep; ++spins)
            if (mGeneration.load(std::memory_order_acquire) != generation) return;
        mGeneration.wait(generation, std::memory_order_acquire);
    }
    void arriveAndWait() { arriveAndWait([] {}); }

private:
    const unsigned mCount;
    std::atomic<unsigned> mWaiting;
    std::atomic<unsigned> mGeneration;
    const unsigned mSpinsBeforeSleep;
};

// Threads get contiguous regions of the model (insertion order, which is also the order
// of the node data) with about equal measured cost. A C component and the Q component it
// talks to are usually neighbours, so they share a thread and their node stays in that
// core's cache; interleaving would bounce every node between cores twice per step.
// Clusters (components of one list linked through a node, core.md §10) go whole to the
// thread of their first member: in the S list their order matters, and in the C and Q
// lists a component may read a signal another one of the same phase writes (a valve's
// spool position feeding a Q component, say), which must happen in list order on one
// thread.
struct Partition {
    std::vector<std::vector<Component*>> s, c, q;
};

Partition partitionByRegion(const std::vector<Component*>& order, const std::vector<Component*>& listS,
                            const std::vector<double>& costS, const std::vector<Component*>& listC,
                            const std::vector<double>& costC, const std::vector<Component*>& listQ,
                            const std::vector<double>& costQ, unsigned threads)
{
    std::map<const Component*, double> cost;
    for (std::size_t i = 0; i < listS.size(); ++i) cost[listS[i]] = costS[i];
    for (std::size_t i = 0; i < listC.size(); ++i) cost[listC[i]] = costC[i];
    for (std::size_t i = 0; i < listQ.size(); ++i) cost[listQ[i]] = costQ[i];
    double total = 0.0;
    for (const auto& [comp, c] : cost) total += c;
    std::map<const Component*, unsigned> threadOf;
    double done = 0.0;
    unsigned t = 0;
    for (const Component* comp : order) {
        auto it = cost.find(comp);
        if (it == cost.end()) continue;   // disabled
        while (t + 1 < threads && done >= total * (t + 1) / threads) ++t;
        threadOf[comp] = t;
        done += it->second;
    }
    Partition p;
    p.s.resize(threads);
    p.c.resize(threads);
    p.q.resize(threads);
    auto assignClusters = [&](const std::vector<Component*>& list, std::vector<std::vector<Component*>>& out) {
        const std::vector<std::size_t> cluster = linkedClusters(list);
        std::map<std::size_t, unsigned> clusterThread;
        for (std::size_t i = 0; i < list.size(); ++i) {
            auto [it, inserted] = clusterThread.emplace(cluster[i], threadOf[list[i]]);
            out[it->second].push_back(list[i]);
        }
    };
    assignClusters(listS, p.s);
    assignClusters(listC, p.c);
    assignClusters(listQ, p.q);
    return p;
}

// Contiguous shares of the logged nodes with about equal numbers of values, one per thread.
// Nodes are in model order, so a share mostly holds nodes its thread just computed.
std::vector<std::pair<std::size_t, std::size_t>> logShares(const std::vector<Node*>& nodes, unsigned threads)
{
    std::size_t total = 0;
    for (const Node* n : nodes) total += n->size();
    std::vector<std::pair<std::size_t, std::size_t>> shares(threads, {nodes.size(), nodes.size()});
    std::size_t begin = 0, done = 0;
    for (unsigned t = 0; t < threads; ++t) {
        const std::size_t target = total * (t + 1) / threads;
        std::size_t end = begin;
        while (end < nodes.size() && (t + 1 == threads || done < target)) done += nodes[end++]->size();
        shares[t] = {begin, end};
        begin = end;
    }
    return shares;
}

// The S phase needs no barrier of its own when no node is shared between an S component
// and a C component of another thread. Without that barrier a thread may start its C
// phase while another is still in its S phase of the same step (Q phases cannot overlap
// an S phase: the C barrier stands between them), so that sharing is the only way the two
// could see each other's values. Region cuts usually split one signal cluster from some
// of its C components; those C clusters are moved whole to the S cluster's thread first.
// Returns whether the S barrier can go.
bool keepSignalPhaseThreadLocal(Partition& p, const std::vector<Component*>& listC)
{
    std::map<const Component*, unsigned> sThread, cThread;
    for (unsigned t = 0; t < p.s.size(); ++t)
        for (const Component* c : p.s[t]) sThread[c] = t;
    for (unsigned t = 0; t < p.c.size(); ++t)
        for (const Component* c : p.c[t]) cThread[c] = t;
    std::map<const Component*, std::size_t> cCluster;
    const std::vector<std::size_t> clusterOfIndex = linkedClusters(listC);
    for (std::size_t i = 0; i < listC.size(); ++i) cCluster[listC[i]] = clusterOfIndex[i];
    auto topLevel = [&](const Component* c) {
        while (c && !cThread.count(c) && !sThread.count(c)) c = c->parentSystem();
        return c;
    };
    // For each C cluster, the threads of the S components it shares a node with.
    std::map<std::size_t, std::set<unsigned>> sThreadsOf;
    std::map<std::size_t, unsigned> clusterThread;
    for (const auto& [comp, thread] : cThread) clusterThread[cCluster[comp]] = thread;
    for (const auto& [comp, thread] : sThread)
        for (Port* port : comp->ports())
            for (Node* n : portNodes(port))
                for (Port* other : n->ports()) {
                    const Component* owner = topLevel(other->component());
                    if (cThread.count(owner)) sThreadsOf[cCluster[owner]].insert(thread);
                }
    bool local = true;
    for (const auto& [cluster, threads] : sThreadsOf) {
        if (threads.size() > 1) {
            local = false;   // shared with S clusters on two threads: keep the barrier
            continue;
        }
        const unsigned to = *threads.begin();
        if (clusterThread[cluster] == to) continue;
        // A named copy: clang 14 cannot capture a structured binding in a lambda.
        const auto moved = cluster;
        for (auto& list : p.c) std::erase_if(list, [&](Component* c) { return cCluster[c] == moved; });
        // Appended in list order: the cluster keeps its own order and depends on nothing
        // else in that thread's list.
        for (Component* c : listC)
            if (cCluster[c] == cluster) p.c[to].push_back(c);
    }
    return local;
}

// Each component's cost is the fastest of its probe steps: an interrupt or page fault
// inside one timed call would otherwise make that component look hundreds of times
// dearer and shift the whole partition.
template <typename Clock>
void timedRun(const std::vector<Component*>& list, std::vector<double>& cost, double t)
{
    for (std::size_t i = 0; i < list.size(); ++i) {
        const auto a = Clock::now();
        list[i]->batchStepper()(&list[i], 1, t);
        cost[i] = std::min(cost[i], std::chrono::duration<double>(Clock::now() - a).count());
    }
}

} // namespace

// Wall time per step of `steps` plain single-threaded steps.
double System::timeSingleThreadedSteps(std::size_t steps, bool& ok)
{
    using Clock = std::chrono::steady_clock;
    const auto begin = Clock::now();
    ok = simulateSteps(steps);
    return std::chrono::duration<double>(Clock::now() - begin).count() / static_cast<double>(steps);
}

bool System::simulateMultiThreaded(double tStop, unsigned threads)
{
    return simulateStepsMultiThreaded(stepsUntil(tStop), threads);
}

// Automatic thread count: more threads only while they are measured to be faster. The run
// first takes some single-threaded steps in windows of about a millisecond (the fastest
// window is the baseline), then goes on with one thread per core, timing the same windows
// for the whole run; once the threads are not clearly faster (ThreadJudge), they stop at a
// step boundary and the rest of the run is single-threaded. Results do not depend on the
// thread count, so switching in the middle of a run changes nothing but the time.
bool System::simulateStepsAutoThreaded(std::size_t n)
{
    const unsigned cores = std::thread::hardware_concurrency();
    if (cores < 2) return simulateSteps(n);
    std::size_t window = 16;
    double single = std::numeric_limits<double>::infinity();
    std::size_t done = 0;
    for (int measured = 0; measured < 3 && done + window <= n;) {
        bool ok = true;
        const double perStep = timeSingleThreadedSteps(window, ok);
        if (!ok) return false;
        if (pauseRequested()) return true;
        done += window;
        if (perStep * static_cast<double>(window) < kTimedWindowSeconds) {
            window *= 2;   // too short to time well: grow the window, this one does not count
            continue;
        }
        single = std::min(single, perStep);
        ++measured;
    }
    const std::size_t rest = n - done;
    // Too short a run to time (no window measured), a step so cheap that it cannot gain from
    // threads (a barrier alone costs about this much), or a short rest: one thread.
    const bool measured = single < std::numeric_limits<double>::infinity();
    if (!measured || single < kMinThreadedStepSeconds || single * static_cast<double>(rest) < kMinThreadedRunSeconds)
        return simulateSteps(rest);
    ThreadJudge judge(single);
    const KeepThreads keepThreads = [&judge](std::size_t takenSteps) {
        const auto now = std::chrono::steady_clock::now().time_since_epoch();
        return judge.keepThreads(takenSteps, std::chrono::duration<double>(now).count());
    };
    return simulateStepsThreadsWhile(rest, std::min(cores, kMaxAutoThreads), window, keepThreads);
}

bool System::simulateStepsThreadsWhile(std::size_t n, unsigned threads, std::size_t window,
                                       const KeepThreads& keepThreads)
{
    const ThreadCheck check{std::max<std::size_t>(window, 1), keepThreads};
    std::size_t taken = 0;
    if (!runThreaded(n, threads, &check, taken)) return false;
    if (taken == n) return true;
    mThreadsUsed = 1;
    return simulateSteps(n - taken);
}

bool System::simulateStepsMultiThreaded(std::size_t n, unsigned threads)
{
    mThreadsUsed = 1;
    // Draws from the one random stream must come in list order to give the same numbers.
    if (mDrawsRandomNumbers) return simulateSteps(n);
    if (threads == 0) return simulateStepsAutoThreaded(n);
    if (threads == 1 || n == 0) return simulateSteps(n);
    std::size_t taken = 0;
    return runThreaded(n, threads, nullptr, taken);
}

// Runs up to `n` steps on `threads` threads (all of them unless a check ends them early);
// `taken` gets the steps actually taken. With a check, thread 0 asks it after a short
// warm-up and then every check->window steps whether the threads go on.
bool System::runThreaded(std::size_t n, unsigned threads, const ThreadCheck* check, std::size_t& taken)
{
    const std::size_t takenBefore = mTakenSteps;
    if (n == 0) return !stopRequested();

    // Measure each component's cost over the first steps (real steps of the run).
    using Clock = std::chrono::steady_clock;
    const std::size_t probeSteps = std::min<std::size_t>(100, n);
    const double unmeasured = std::numeric_limits<double>::infinity();
    std::vector<double> costS(mS.size(), unmeasured), costC(mC.size(), unmeasured), costQ(mQ.size(), unmeasured);
    for (std::size_t step = 0; step < probeSteps; ++step) {
        if (interrupted()) {
            taken = mTakenSteps - takenBefore;
            return !stopRequested();
        }
        mTime += mTimestep;
        timedRun<Clock>(mS, costS, mTime);
        timedRun<Clock>(mC, costC, mTime);
        timedRun<Clock>(mQ, costQ, mTime);
        ++mTakenSteps;
        logSample();
    }
    Partition part = partitionByRegion(mOrder, mS, costS, mC, costC, mQ, costQ, threads);
    const bool barrierAfterS = !keepSignalPhaseThreadLocal(part, mC);
    // Each thread's share of a list as batches: regrouping inside a share is safe for the
    // same reason as splitting the list by cluster.
    const StepBatches::Order order = StepBatches::Order::Regroup;
    std::vector<StepBatches> partS, partC, partQ;
    for (unsigned id = 0; id < threads; ++id) {
        partS.emplace_back(part.s[id], order);
        partC.emplace_back(part.c[id], order);
        partQ.emplace_back(part.q[id], order);
    }

    // Per step: S | C | Q phases with a barrier after each (after S only when some node is
    // shared across threads between S and C components). Every thread advances its own
    // copy of the time by the same additions, so all see the same value. On steps that
    // store a log sample every thread then copies its share of the logged nodes into the
    // slot, and one more barrier keeps the next step's S phase from overwriting a node
    // another thread is still copying. Only the master touches the time and counters, and
    // it counts a row as logged only after that barrier: a progress callback may read it.
    std::vector<char> logsAfter(n - probeSteps, 0);
    for (std::size_t k = mLogCounter; k < mLogSteps.size(); ++k) {
        const std::size_t step = mLogSteps[k];
        if (step > mTakenSteps && step - mTakenSteps - 1 < logsAfter.size()) logsAfter[step - mTakenSteps - 1] = 1;
    }
    const auto shares = logShares(mLoggedNodes, threads);
    SpinBarrier barrier(threads);
    bool endSnapshot = false;   // written only by the last thread at the Q barrier
    std::atomic<bool> giveUp{false};
    const double startTime = mTime;
    const std::size_t firstSlot = mLogCounter;
    // Thread 0 asks the check at window boundaries after a warm-up (thread start, caches).
    constexpr std::size_t warmUpSteps = 16;
    auto askCheck = [&](std::size_t step) {
        if (step < warmUpSteps || (step - warmUpSteps) % check->window != 0) return;
        if (!check->keepThreads(mTakenSteps)) giveUp.store(true, std::memory_order_relaxed);
    };
    auto run = [&](unsigned id) {
        double t = startTime;
        std::size_t slot = firstSlot;
        for (std::size_t step = 0; step < logsAfter.size(); ++step) {
            if (id == 0 && check) askCheck(step);
            t += mTimestep;
            partS[id].step(t);
            if (barrierAfterS) barrier.arriveAndWait();
            partC[id].step(t);
            barrier.arriveAndWait();
            partQ[id].step(t);
            barrier.arriveAndWait([&] { endSnapshot = interrupted() || giveUp.load(std::memory_order_relaxed); });
            if (logsAfter[step]) {
                for (std::size_t k = shares[id].first; k < shares[id].second; ++k) mLoggedNodes[k]->logSample(slot);
                barrier.arriveAndWait();
            }
            if (id == 0) {
                mTime = t;
                ++mTakenSteps;
                if (logsAfter[step]) {
                    mLogTime[slot] = t;
                    ++mLogCounter;
                }
                if (mProgress && mProgressInterval && (mTakenSteps % mProgressInterval) == 0)
                    mProgress(mProgressUser, mTakenSteps - takenBefore, n);
            }
            if (logsAfter[step]) ++slot;
            if (endSnapshot) return;
        }
    };
    mThreadsUsed = threads;
    std::vector<std::thread> pool;
    for (unsigned id = 1; id < threads; ++id) pool.emplace_back(run, id);
    run(0);
    for (auto& th : pool) th.join();
    taken = mTakenSteps - takenBefore;
    return !stopRequested();
}

} // namespace tlmhub
