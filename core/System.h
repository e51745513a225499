#pragma once
// A system: components, their connections, system parameters and system ports, and the
// simulation loop (core.md §2.5-§4). Systems nest: a subsystem is a component of its parent.
#include "core/Component.h"
#include "core/GuiLayout.h"
#include "core/LogArena.h"
#include "core/Status.h"
#include "core/StepBatches.h"

#include <atomic>
#include <functional>
#include <map>
#include <mutex>
#include <memory>
#include <string>
#include <vector>

namespace tlmhub {

namespace ParameterEvaluator { struct Pass; }

// What a model file says of a system port or a connection beyond its names: the typed
// layout (core/GuiLayout.h) and the other children of its element, kept as serialized XML
// (see Component::preservedXml). One record, so renaming or moving one moves both.
struct SystemPortExtras {
    ObjectLayout layout;
    std::string preservedXml;
};
struct ConnectionExtras {
    ConnectionLayout layout;   // points from the key's first end to its second
    std::string preservedXml;
};

class System : public Component {
public:
    System();
    ~System() override;

    CqsKind kind() const override { return mSystemKind; }
    System* rootSystem();
    const System* rootSystem() const;
    bool isRoot() const { return parentSystem() == nullptr; }

    // Conditional subsystem: simulates only while its input `on` > 0.
    void makeConditional();
    bool isConditional() const { return mOnPort != nullptr; }

    // ---- editing (names are sanitised and made unique; the actual name is returned) ----
    std::string addComponent(std::unique_ptr<Component> component);
    Status removeComponent(const std::string& name);
    // The actual new name (sanitised, made unique).
    Result<std::string> renameComponent(const std::string& oldName, const std::string& newName);
    Component* component(const std::string& name) const;
    System* subsystem(const std::string& name) const;
    // Sub-components in byte-wise name order.
    std::vector<Component*> componentsByName() const;
    // Number of ordinary components, counting into subsystems.
    std::size_t countComponents() const;
    // Sub-components in insertion order (the simulation lists derive from it).
    const std::vector<Component*>& componentsInOrder() const { return mOrder; }

    Port* addSystemPort(const std::string& desiredName);
    // The actual new name (sanitised, made unique); the port's layout and its connections' lines
    // follow it. Deleting disconnects it inside and out and drops its layout.
    Result<std::string> renameSystemPort(const std::string& oldName, const std::string& newName);
    Status deleteSystemPort(const std::string& name);
    Port* systemPort(const std::string& name) const;

    // not_found for names that name no port; illegal_connection with the reason, naming both
    // ports (for disconnect: ports not connected to each other). A system port is named by
    // its name as both component and port.
    Status connect(const std::string& compA, const std::string& portA, const std::string& compB,
                   const std::string& portB);
    Status disconnect(const std::string& compA, const std::string& portA, const std::string& compB,
                      const std::string& portB);

    // System parameters live in parameters(); type given by name ("double", ...).
    Status setSystemParameter(const std::string& name, const std::string& value,
                              const std::string& type, const std::string& description,
                              const std::string& unit, bool internal);
    bool removeSystemParameter(const std::string& name);

    // ---- grouping (core.md §2.7; SystemGrouping.cpp) ----
    // Moves the named components into a new subsystem at the place of the first of them.
    // A connection crossing the boundary goes through a system port of the subsystem, one
    // port per node. Returns the subsystem's actual name; on failure (not_found,
    // illegal_grouping) the model is unchanged.
    Result<std::string> group(const std::vector<std::string>& names, const std::string& subsystemName);
    // The inverse: the subsystem's components (renamed if their names are taken) and its
    // system parameters move into this system at its place, reconnected through its system
    // ports, and the subsystem is removed. Returns the components' names here; on failure
    // the model is unchanged.
    Result<std::vector<std::string>> ungroup(const std::string& subsystemName);

    // ---- names ----
    bool isNameTaken(const std::string& name) const;
    std::string uniqueName(const std::string& desired) const;

    // ---- simulation settings ----
    double desiredTimestep = 0.001;
    bool inheritTimestep = true;
    std::size_t requestedLogSamples = 0;
    double logStartTime = 0.0;
    void setTimestep(double ts) override;
    // Passes preInitialize on to every component inside, S then C then Q, as Hopsan does
    // (components set sort hints there from their parameters, before any list is sorted).
    void preInitialize() override;

    // ---- running ----
    // Structure checks before a run, then every parameter evaluated: the first problem
    // found, with its code and model path.
    Status check();
    // Root: initialises every component for a run from startTime; a component that fails
    // (stopSimulation in its initialize()) gives init_failed with its reason and path.
    // AlreadyEvaluated skips evaluating the parameters again: for a caller that ran check()
    // and changed no parameter since (Simulation does).
    enum class ParameterEvaluation { Evaluate, AlreadyEvaluated };
    Status initialize(double startTime, double stopTime,
                      ParameterEvaluation evaluation = ParameterEvaluation::Evaluate);
    bool simulate(double stopTime);   // root: runs until stopTime
    // The same steps with the root's S, C and Q lists split over `threads` threads (S
    // components by signal cluster, see MultiThreadedSimulation.cpp); 0 = automatic: one per
    // core while that is measured to be faster than one thread (re-checked throughout the
    // run, see core/ThreadJudge.h), else one. Results are identical to simulate().
    bool simulateMultiThreaded(double stopTime, unsigned threads);
    // Root: the next `steps` steps (runs can be continued step-exactly this way).
    bool simulateSteps(std::size_t steps);
    bool simulateStepsMultiThreaded(std::size_t steps, unsigned threads);
    // The threaded part of the automatic choice with its judge given, for tests: `threads`
    // threads, and after every `window` steps on them keepThreads(steps the run has taken)
    // says whether they go on; from the first no, the rest is single-threaded.
    using KeepThreads = std::function<bool(std::size_t takenSteps)>;
    bool simulateStepsThreadsWhile(std::size_t steps, unsigned threads, std::size_t window,
                                   const KeepThreads& keepThreads);
    // Threads the latest steps ran on.
    unsigned threadsUsed() const { return mThreadsUsed; }
    // Number of root steps from the current time to `stopTime` (Hopsan's rounding).
    std::size_t stepsUntil(double stopTime) const;
    void finalize() override;
    // Safe to call from any thread (a server's cancel, a component on a worker thread).
    void requestStop() { mStopRequested.store(true, std::memory_order_relaxed); }
    bool stopRequested() const { return mStopRequested.load(std::memory_order_relaxed); }
    // Safe to call from any thread: the run in progress returns early at a step boundary, as
    // on a stop, but the system stays ready to go on (Simulation's RunOptions::pause).
    void requestPause() { mPauseRequested.store(true, std::memory_order_relaxed); }
    bool pauseRequested() const { return mPauseRequested.load(std::memory_order_relaxed); }
    void clearPauseRequest() { mPauseRequested.store(false, std::memory_order_relaxed); }
    // A stop or a pause: the step loops end.
    bool interrupted() const { return stopRequested() || pauseRequested(); }
    // Progress callback for long runs (root only): called every `interval` steps.
    using ProgressCallback = void (*)(void* user, std::size_t stepsTaken, std::size_t stepsTotal);
    void setProgressCallback(ProgressCallback cb, void* user, std::size_t interval);

    std::size_t takenSteps() const { return mTakenSteps; }

    // Every node of the root and its subsystems, each once.
    std::vector<Node*> allNodes();

    // ---- results ----
    const std::vector<double>& logTime() const { return mLogTime; }
    std::size_t numLoggedSamples() const { return mLogCounter; }
    std::size_t numLogSlots() const { return mLogSteps.size(); }

    // ---- messages (root) ----
    // Messages of the last load/run. Not for use while a run is going on.
    std::vector<Message>& messages() { return rootSystem()->mMessages; }
    // Thread-safe append (components report through Component::addMessage).
    void postMessage(Message m);
    std::string modelDirectory;   // root: directory of the loaded model file

    // Used by the loader: a system parameter value string may fail to evaluate until
    // everything is loaded; it is stored anyway ("forced").
    double startTime = 0.0;   // root: from <simulationtime start>
    double stopTime = 2.0;

    // Subsystem step driven by the parent (internal).
    void simulateTo(double parentTime);

    // Aliases: alias name -> "Comp#Port#Var".
    std::map<std::string, std::string> aliases;

    // An external subsystem's file (relative to the parent model); empty if embedded.
    std::string externalPath;

    // Model-file content beyond the simulated model (see Component::preservedXml): root
    // document extras, per system port (by name), per connection (by "a.pa|b.pb",
    // core/hmf/PreservedXml.h's connectionKey), and unknown objects.
    std::string preservedDocumentXml;
    std::map<std::string, SystemPortExtras> systemPortExtras;
    std::map<std::string, ConnectionExtras> connectionExtras;
    std::vector<std::string> preservedObjectsXml;
    // The root's live controls (core/GuiLayout.h), in the order the web app lists them.
    std::vector<LiveControlLayout> liveControls;

private:
    // A subsystem starts inside its parent's initialize(startTime, stopTime), never through
    // the component hook; naming the hook here keeps it from being hidden yet uncallable.
    using Component::initialize;
    friend class Component;
    void determineKind();
    // A renamed system port's layout, and its connections' lines inside and out, follow it;
    // an empty newName (a deleted port) drops them.
    void moveSystemPortLayout(const std::string& oldName, const std::string& newName);
    // The kind a subsystem gets from the inner ports attached to its system ports.
    static CqsKind interfaceKind(const std::vector<const Port*>& innerPorts);
    std::unique_ptr<Component> releaseComponent(Component* c);
    // addComponent at a place in the insertion order.
    std::string insertComponent(std::unique_ptr<Component> c, std::size_t orderPosition);
    void moveToEnd(Component* c);
    void buildRunLists();
    Status sortList(std::vector<Component*>& list, bool failOnLoop);
    void computeSortHintsOfSystemPorts();
    Status checkStructure();
    // Every parameter, system parameters first, in one pass (values computed once each).
    Status evaluateParameters(ParameterEvaluator::Pass& pass);
    void loadStartValues();
    void computeLogSchedule(double t0, double t1);
    void allocateLogStorage();
    void logSample();
    void buildStepBatches(StepBatches::Order order);
    void stepOnce();
    void packNodeData();

    // How a threaded run of the automatic choice asks whether its threads go on.
    struct ThreadCheck {
        std::size_t window;   // steps between two questions
        const KeepThreads& keepThreads;
    };
    bool simulateStepsAutoThreaded(std::size_t steps);
    double timeSingleThreadedSteps(std::size_t steps, bool& ok);
    bool runThreaded(std::size_t steps, unsigned threads, const ThreadCheck* check, std::size_t& taken);
    Status initializeInternal(double startTime, double stopTime, ParameterEvaluation evaluation);
    Status initFailure(const Component& c) const;
    void propagateTimestep();
    Result<Port*> resolvePort(const std::string& compName, const std::string& portName) const;
    // Connects two resolved ports; the reason if refused (empty if connected).
    std::string connectPorts(Port* a, Port* b);

    CqsKind mSystemKind = CqsKind::Undefined;
    std::map<std::string, std::unique_ptr<Component>> mComponents;
    std::vector<Component*> mOrder;                // insertion order
    std::vector<Component*> mS, mC, mQ;            // run lists (sorted at initialize)
    StepBatches mBatchS, mBatchC, mBatchQ;         // the same, as the step runs them
    std::vector<Component*> mDisabled;
    Port* mOnPort = nullptr;
    double* mpOn = nullptr;

    std::vector<Message> mMessages;
    RandomStream mRandom;                // root: the noise sources' numbers
    bool mDrawsRandomNumbers = false;    // root: some component took mRandom at initialize
    std::atomic<bool> mStopRequested{false};
    std::atomic<bool> mPauseRequested{false};
    std::mutex mMessagesMutex;
    std::size_t mTakenSteps = 0;
    unsigned mThreadsUsed = 1;

    // logging
    std::vector<std::size_t> mLogSteps;
    std::vector<double> mLogTime;
    std::size_t mLogCounter = 0;
    std::vector<Node*> mLoggedNodes;
    LogArena mLogArena;   // the logged samples of mLoggedNodes, one row per log step
    std::size_t mLogRowSize = 0;
    struct LogCopy {
        const double* from;   // node data, contiguous for `count` values
        std::size_t count;
    };
    std::vector<LogCopy> mLogCopies;   // a row's values, in row order

    // Root: every node's data in one contiguous block (filled at initialize).
    std::vector<double> mNodeArena;

    ProgressCallback mProgress = nullptr;
    void* mProgressUser = nullptr;
    std::size_t mProgressInterval = 0;
};

// Sanitise a name as Hopsan does: bytes other than [A-Za-z0-9_] become '_'; empty -> noName.
std::string sanitizeName(const std::string& name);

} // namespace tlmhub
