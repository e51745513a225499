#include "core/Simulation.h"

#include "core/ParameterPath.h"
#include "core/SystemCopy.h"
#include "core/numerics/StepCount.h"

#include <cmath>
#include <utility>

namespace tlmhub {

namespace {

struct ProgressRelay {
    const RunOptions* options;
    const System* root;
    std::size_t totalSteps;
    static void call(void* user, std::size_t, std::size_t)
    {
        auto* relay = static_cast<ProgressRelay*>(user);
        relay->options->progress(relay->root->takenSteps(), relay->totalSteps);
    }
};

// The node slot a change while running writes: the start value's slot in its port's node.
struct LiveTarget {
    Port* port;
    int slot;
};

// Where a change while running of `parameter` goes, or restart_required naming `path` when
// only a new start applies it: the component type did not declare it live-changeable, or it
// is an input that takes its value from a connection.
Result<LiveTarget> liveTarget(const Component& owner, const Parameter& parameter, const std::string& path)
{
    const std::size_t hash = parameter.name.find('#');
    Port* port = parameter.isStartValue ? owner.port(parameter.name.substr(0, hash)) : nullptr;
    if (!parameter.liveChangeable || !port || port->isMultiport())
        return Status{StatusCode::RestartRequired,
                      "parameter '" + path + "' cannot change while the simulation runs: reset, set it and run again",
                      path};
    if (port->kind() == PortKind::Read && port->isConnected())
        return Status{StatusCode::RestartRequired,
                      "input '" + path + "' takes its value from its connection: disconnect it and run again", path};
    const int slot = nodeVariableIndex(port->nodeType(), std::string_view(parameter.name).substr(hash + 1));
    if (slot < 0)
        return Status{StatusCode::RestartRequired, "parameter '" + path + "' names no node variable", path};
    return LiveTarget{port, slot};
}

// Every component of `system` and its subsystems, in model order (subsystems before what
// they hold).
template <typename Visit>
void forEachComponent(const System& system, const Visit& visit)
{
    for (Component* c : system.componentsInOrder()) {
        visit(*c);
        if (c->isSystem()) forEachComponent(static_cast<const System&>(*c), visit);
    }
}

} // namespace

const char* simulationStateName(SimulationState state)
{
    switch (state) {
    case SimulationState::Compiled: return "compiled";
    case SimulationState::Initialised: return "initialised";
    case SimulationState::Running: return "running";
    case SimulationState::Paused: return "paused";
    case SimulationState::Finished: return "finished";
    case SimulationState::Stopped: return "stopped";
    case SimulationState::Failed: return "failed";
    }
    return "unknown";
}

Result<Simulation> compile(System& root, const SimulationSettings& settings)
{
    const double start = settings.startTime.value_or(root.startTime);
    const double stop = settings.stopTime.value_or(root.stopTime);
    const double timestep = settings.timestep.value_or(root.desiredTimestep);
    if (!std::isfinite(start) || !std::isfinite(stop) || !(stop >= start))
        return Status{StatusCode::InvalidSettings, "need finite times with stop >= start"};
    if (!std::isfinite(timestep) || !(timestep > 0.0))
        return Status{StatusCode::InvalidSettings, "need a positive time step"};
    root.desiredTimestep = timestep;
    if (settings.logSamples) root.requestedLogSamples = *settings.logSamples;
    Status checked = root.check();
    if (!checked) return checked;
    return Simulation(root, start, stop, timestep);
}

Result<Simulation> compile(std::unique_ptr<System> root, const SimulationSettings& settings)
{
    if (!root) return Status{StatusCode::InvalidModel, "no model to compile"};
    Result<Simulation> compiled = compile(*root, settings);
    if (compiled) compiled->mOwnedRoot = std::move(root);
    return compiled;
}

Result<Simulation> compile(const Model& model, const SimulationSettings& settings)
{
    Result<std::unique_ptr<System>> copy = copySystem(model.root());
    if (!copy) return copy.status();
    return compile(std::move(*copy), settings);
}

Result<Simulation> compile(Model&& model, const SimulationSettings& settings)
{
    return compile(model.releaseRoot(), settings);
}

Simulation::Simulation(System& root, double start, double stop, double timestep)
    : mRoot(&root), mStartTime(start), mStopTime(stop), mTimestep(timestep),
      mTotalSteps(roundSteps((stop - start) / timestep)), mNodes(root.allNodes())
{
    for (const Node* n : mNodes) mStartValues.insert(mStartValues.end(), n->data(), n->data() + n->size());
}

Simulation::Simulation(Simulation&& other) noexcept { *this = std::move(other); }

Simulation& Simulation::operator=(Simulation&& other) noexcept
{
    if (this == &other) return *this;
    if (mRoot && (mState == SimulationState::Initialised || mState == SimulationState::Paused))
        mRoot->finalize();
    mRoot = std::exchange(other.mRoot, nullptr);
    mOwnedRoot = std::move(other.mOwnedRoot);
    mStartTime = other.mStartTime;
    mStopTime = other.mStopTime;
    mTimestep = other.mTimestep;
    mState = other.mState;
    mTotalSteps = other.mTotalSteps;
    mParametersEvaluated = other.mParametersEvaluated;
    mLiveChanges = std::move(other.mLiveChanges);
    mNodes = std::move(other.mNodes);
    mStartValues = std::move(other.mStartValues);
    return *this;
}

Simulation::~Simulation()
{
    // Components get their finalize() also when a run was left unfinished.
    if (mRoot && (mState == SimulationState::Initialised || mState == SimulationState::Paused))
        mRoot->finalize();
}

double Simulation::time() const { return mState == SimulationState::Compiled ? mStartTime : mRoot->time(); }

std::size_t Simulation::takenSteps() const { return mState == SimulationState::Compiled ? 0 : mRoot->takenSteps(); }

std::size_t Simulation::totalSteps() const { return mTotalSteps; }

std::size_t Simulation::logSlots() const { return mState == SimulationState::Compiled ? 0 : mRoot->numLogSlots(); }

ResultView Simulation::results() const { return ResultView(*mRoot); }

const std::vector<Message>& Simulation::messages() const { return mRoot->messages(); }

void Simulation::requestStop() { mRoot->requestStop(); }

// A run that ended early: the first error a component reported (its text and model path),
// else the end a component designed (SimulationEnded), else the fallback message.
Status Simulation::stopped(const std::string& fallbackMessage) const
{
    const Message* designedEnd = nullptr;
    for (const Message& m : mRoot->messages()) {
        if (m.type == MessageType::Error || m.type == MessageType::Fatal)
            return {StatusCode::SimulationStopped, m.text, m.source};
        if (m.code == StatusCode::SimulationEnded && !designedEnd) designedEnd = &m;
    }
    if (designedEnd) return {StatusCode::SimulationEnded, designedEnd->text, designedEnd->source};
    return {StatusCode::SimulationStopped, fallbackMessage};
}

void Simulation::finish(SimulationState state)
{
    mRoot->finalize();
    mState = state;
}

Status Simulation::initialise()
{
    if (mState != SimulationState::Compiled)
        return {StatusCode::InvalidState, std::string("cannot initialise a simulation that is ") +
                                              simulationStateName(mState) + " (reset it first)"};
    mRoot->messages().clear();
    const auto evaluation = mParametersEvaluated ? System::ParameterEvaluation::AlreadyEvaluated
                                                 : System::ParameterEvaluation::Evaluate;
    mParametersEvaluated = true;
    if (Status started = mRoot->initialize(mStartTime, mStopTime, evaluation); !started) {
        finish(SimulationState::Failed);
        return started;
    }
    mState = SimulationState::Initialised;
    return Status::ok();
}

Status Simulation::run(double until, const RunOptions& options)
{
    // Steps are counted from the start, so a run continued in pieces takes exactly the steps
    // of one whole run.
    const std::size_t target = std::min(roundSteps((until - mStartTime) / mTimestep), mTotalSteps);
    const std::size_t taken = takenSteps();
    return runSteps(target > taken ? target - taken : 0, options);
}

Status Simulation::runSteps(std::size_t requested, const RunOptions& options)
{
    switch (mState) {
    case SimulationState::Compiled: {
        Status started = initialise();
        if (!started) return started;
        break;
    }
    case SimulationState::Initialised:
    case SimulationState::Paused: break;
    default:
        return {StatusCode::InvalidState,
                std::string("cannot run a simulation that is ") + simulationStateName(mState) +
                    " (reset it first)"};
    }
    applyLiveChanges();
    const std::size_t left = mTotalSteps > mRoot->takenSteps() ? mTotalSteps - mRoot->takenSteps() : 0;
    const std::size_t steps = std::min(requested, left);

    ProgressRelay relay{&options, mRoot, mTotalSteps};
    if (options.progress && options.progressInterval)
        mRoot->setProgressCallback(&ProgressRelay::call, &relay, options.progressInterval);
    std::stop_callback onStop(options.stop, [this] { mRoot->requestStop(); });
    // A pause ends only the run it was asked for in (one already asked for ends it at once).
    mRoot->clearPauseRequest();
    std::stop_callback onPause(options.pause, [this] { mRoot->requestPause(); });
    mState = SimulationState::Running;
    bool ok = !options.stop.stop_requested();
    if (ok) ok = mRoot->simulateStepsMultiThreaded(steps, options.threads);
    mRoot->setProgressCallback(nullptr, nullptr, 0);

    if (!ok) {
        finish(SimulationState::Stopped);
        char when[64];
        std::snprintf(when, sizeof when, "%g", mRoot->time());
        return stopped(std::string("simulation stopped at t=") + when);
    }
    if (mRoot->takenSteps() >= mTotalSteps) finish(SimulationState::Finished);
    else mState = SimulationState::Paused;
    return Status::ok();
}

Status Simulation::reset()
{
    if (mState == SimulationState::Running)
        return {StatusCode::InvalidState, "cannot reset a running simulation"};
    if (mState == SimulationState::Initialised || mState == SimulationState::Paused) mRoot->finalize();
    std::size_t offset = 0;
    for (Node* n : mNodes) {
        std::copy(mStartValues.begin() + static_cast<std::ptrdiff_t>(offset),
                  mStartValues.begin() + static_cast<std::ptrdiff_t>(offset + n->size()), n->data());
        offset += n->size();
    }
    mRoot->messages().clear();
    mLiveChanges.clear();   // a change while running is to that run, not to the model
    mState = SimulationState::Compiled;
    return Status::ok();
}

Status Simulation::setParameter(const std::string& path, const std::string& value)
{
    if (mState == SimulationState::Running || mState == SimulationState::Initialised ||
        mState == SimulationState::Paused)
        return {StatusCode::InvalidState, "parameters change between runs: reset the simulation first", path};
    if (Status set = setParameterValue(*mRoot, path, value); !set) return set;
    mParametersEvaluated = false;   // its dependents are evaluated again at the next start
    return Status::ok();
}

Status Simulation::changeWhileRunning(const std::string& path, double value)
{
    if (mState != SimulationState::Compiled && mState != SimulationState::Initialised &&
        mState != SimulationState::Paused)
        return {StatusCode::InvalidState,
                std::string("values change between the steps of a simulation, not while it is ") +
                    simulationStateName(mState),
                path};
    Result<ParameterRef> found = findParameter(*mRoot, path);
    if (!found) return found.status();
    Result<LiveTarget> target = liveTarget(*found->owner, *found->parameter, path);
    if (!target) return target.status();
    if (!std::isfinite(value))
        return {StatusCode::InvalidParameter, "parameter '" + path + "' needs a finite number", path};
    Node* node = target->port->node();
    for (LiveChange& pending : mLiveChanges) {
        if (pending.node == node && pending.slot == target->slot) {
            pending.value = value;   // the later of two changes before one step wins
            return Status::ok();
        }
    }
    mLiveChanges.push_back({node, target->slot, value});
    return Status::ok();
}

void Simulation::applyLiveChanges()
{
    for (const LiveChange& change : mLiveChanges) change.node->setValue(change.slot, change.value);
    mLiveChanges.clear();
}

std::vector<LiveValue> Simulation::liveValues() const
{
    std::vector<LiveValue> values;
    forEachComponent(*mRoot, [&](const Component& component) {
        for (const auto& parameter : component.parameters().all()) {
            if (!parameter->liveChangeable) continue;
            const std::string name = parameter->name.substr(0, parameter->name.find('#'));
            const std::string path = component.modelPath() + "." + name;
            Result<LiveTarget> target = liveTarget(component, *parameter, path);
            if (!target) continue;
            const Node* node = target->port->node();
            // Before the first start the node does not hold the start value yet.
            double value = mState == SimulationState::Compiled
                               ? target->port->startValues[static_cast<std::size_t>(target->slot)]
                               : node->value(target->slot);
            for (const LiveChange& pending : mLiveChanges)
                if (pending.node == node && pending.slot == target->slot) value = pending.value;
            values.push_back({path, value, parameter->unit});
        }
    });
    return values;
}

} // namespace tlmhub
