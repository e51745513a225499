#pragma once
// A model compiled for running: the one way the CLI, validation, the server and the tests
// run a System.
//
//   auto sim = compile(root, {.stopTime = 2.0});
//   if (!sim) report(sim.status());
//   sim->run(1.0);                   // resumable: run(1.0) then run(2.0) == run(2.0)
//   sim->run(2.0, {.threads = 2});   // also when a RunOptions::pause request ended run(1.0) early
//   ResultView results = sim->results();
//   sim->setParameter("Mass.m", "20");
//   sim->reset();                    // back to the start; the new value and what depends on it apply
//   sim->run();
//
// Between two steps a simulation also takes new values for the parameters that may change
// while it runs (liveValues() lists them; a server's live session):
//
//   sim->runSteps(1000);
//   sim->changeWhileRunning("Step.y_A", 0.8);   // applied before the next step
//   sim->run();                                 // == a run paused at step 1000, changed, continued
//
// States: compiled -> (first run initialises) initialised -> running -> paused (stopped
// before the stop time on request of run's `until` or RunOptions::pause) / finished / stopped / failed.
// reset() returns to compiled from any state but running. Log storage is allocated when a
// run starts from compiled, not at compile.
//
// compile(const Model&) runs a copy of the model: the Model stays editable and may be
// compiled again, also on other threads at once. compile(Model&&) and
// compile(std::unique_ptr<System>) hand the model over instead (no copy): the Simulation then
// stands alone (a server holds queued jobs this way). compile(System&) borrows the system: it
// must outlive the Simulation and not be edited while one exists.
#include "core/Model.h"
#include "core/ResultView.h"
#include "core/Status.h"
#include "core/System.h"

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <stop_token>
#include <string>
#include <vector>

namespace tlmhub {

// Unset fields take the model's own values.
struct SimulationSettings {
    std::optional<double> startTime = {};
    std::optional<double> stopTime = {};
    std::optional<double> timestep = {};
    std::optional<std::size_t> logSamples = {};
};

struct RunOptions {
    // Results do not depend on it. autoThreads: one per core while the run measures that to be
    // faster than one thread (checked throughout the run, core/ThreadJudge.h), else one.
    unsigned threads = 1;
    static constexpr unsigned autoThreads = 0;
    // Called on the running thread every `progressInterval` steps with the steps taken since
    // the start and the steps of the whole run.
    std::function<void(std::size_t stepsTaken, std::size_t stepsTotal)> progress = {};
    std::size_t progressInterval = 0;
    std::stop_token stop = {};   // a stop request ends the run (state stopped)
    // A request ends the run early at a step boundary (state paused): a later run goes on
    // from there and gives the same results (a server's time slices).
    std::stop_token pause = {};
};

// A parameter that may change while the simulation runs (Simulation::liveValues).
struct LiveValue {
    std::string path;     // as jobs name parameters: "Step.y_A", "Sub$Gain.k"
    double value = 0.0;   // the value the next step uses
    std::string unit;
};

enum class SimulationState { Compiled, Initialised, Running, Paused, Finished, Stopped, Failed };
const char* simulationStateName(SimulationState state);

class Simulation {
public:
    Simulation(Simulation&& other) noexcept;
    Simulation& operator=(Simulation&& other) noexcept;
    Simulation(const Simulation&) = delete;
    Simulation& operator=(const Simulation&) = delete;
    ~Simulation();

    // Compiled -> initialised: allocates the logs, evaluates the parameters and initialises
    // the components at the start time. run() does it when needed.
    Status initialise();
    // Simulates from the current time up to `until` (at most the stop time).
    Status run(double until, const RunOptions& options = {});
    Status run(const RunOptions& options = {}) { return run(mStopTime, options); }
    // The next `steps` steps (fewer if the stop time comes first); run in slices this way, a
    // caller can change the options between them.
    Status runSteps(std::size_t steps, const RunOptions& options = {});

    // Back to the state right after compile (node values as before the first run).
    Status reset();
    // A path as core/ParameterPath.h names it ("Comp.param", "Sub$Comp.param", "param"). The
    // value must evaluate; it takes effect from the next start (after reset(), or at once
    // while the simulation is still compiled).
    Status setParameter(const std::string& path, const std::string& value);

    // A new value, from the next step on, for a parameter that may change while the
    // simulation runs: the start value of a variable whose node its component reads every
    // step, as the component type declares (Parameter::liveChangeable): an unconnected input
    // variable ("Step.y_A", "Gain.k", "Saturation.y_upper") or a constant source's output
    // ("Constant.y"). Allowed while compiled, initialised or paused (between runSteps/run
    // slices, never from inside a run: invalid_state then, and once finished, stopped or
    // failed). A parameter only a new start applies (a constant such as a mass, an initial
    // value, an input its type reads only in initialize(), a connected input) gives
    // restart_required with its path, an unknown one unknown_parameter, a value that is not
    // finite invalid_parameter.
    // The change is to the run, not to the model: the parameter keeps its value string, and
    // reset() goes back to the model's values (setParameter changes the model).
    Status changeWhileRunning(const std::string& path, double value);
    // Every parameter changeWhileRunning accepts now, in model order, with the value the
    // next step uses.
    std::vector<LiveValue> liveValues() const;

    // Thread-safe: ends a run in progress (state stopped).
    void requestStop();

    SimulationState state() const { return mState; }
    double startTime() const { return mStartTime; }
    double stopTime() const { return mStopTime; }
    double timestep() const { return mTimestep; }
    double time() const;
    std::size_t takenSteps() const;
    std::size_t totalSteps() const;   // steps from the start to the stop time
    std::size_t logSlots() const;     // samples a full run logs (known once initialised)
    unsigned threadsUsed() const { return mRoot->threadsUsed(); }   // by the latest steps

    // The samples logged so far.
    ResultView results() const;
    // Warnings and errors of the last start and run.
    const std::vector<Message>& messages() const;

    System& system() { return *mRoot; }
    const System& system() const { return *mRoot; }

private:
    friend Result<Simulation> compile(System& root, const SimulationSettings& settings);
    friend Result<Simulation> compile(std::unique_ptr<System> root, const SimulationSettings& settings);
    Simulation(System& root, double start, double stop, double timestep);
    Status stopped(const std::string& fallbackMessage) const;
    void finish(SimulationState state);

    System* mRoot = nullptr;
    std::unique_ptr<System> mOwnedRoot;   // set when compile took the System over
    double mStartTime = 0.0, mStopTime = 0.0, mTimestep = 0.0;
    SimulationState mState = SimulationState::Compiled;
    std::size_t mTotalSteps = 0;
    // compile() evaluated every parameter; a setParameter() since asks for it again.
    bool mParametersEvaluated = true;
    // Changes asked for by changeWhileRunning since the last step, applied before the next
    // one (the first run's start rewrites the node values, so they wait until then). The
    // node is found when the change is asked for; the step loop never sees this.
    struct LiveChange {
        Node* node;
        int slot;
        double value;
    };
    std::vector<LiveChange> mLiveChanges;
    void applyLiveChanges();
    // Node values from before the first run, for reset().
    std::vector<Node*> mNodes;
    std::vector<double> mStartValues;
};

// Checks the model (structure, connections, every parameter) and applies the settings.
Result<Simulation> compile(System& root, const SimulationSettings& settings = {});
// The same, and the Simulation owns the System from then on.
Result<Simulation> compile(std::unique_ptr<System> root, const SimulationSettings& settings = {});
// The same for a model: a copy of it (the Model stays as it is), or the model itself.
Result<Simulation> compile(const Model& model, const SimulationSettings& settings = {});
Result<Simulation> compile(Model&& model, const SimulationSettings& settings = {});

} // namespace tlmhub
