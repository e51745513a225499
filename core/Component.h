#pragma once
// Component base class: the authoring API every component type uses (core.md §2).
//
// A component type derives from ComponentC, ComponentQ or ComponentSignal and overrides
//   configure()            register ports, constants, input/output variables
//   initialize()           bind node pointers, write initial c/Zc or outputs
//   simulateOneTimestep()  the equations of one step (mTime already advanced)
//   finalize()             optional
// and registers itself with TLMHUB_REGISTER_COMPONENT in its own .cpp file.
#include "core/GuiLayout.h"
#include "core/Node.h"
#include "core/NodeTypes.h"
#include "core/Parameter.h"
#include "core/Port.h"
#include "core/Status.h"
#include "core/numerics/RandomStream.h"

#include <cstddef>
#include <initializer_list>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace tlmhub {

class System;
class Component;

// Steps `count` components of one type at `time`: one batch of a run list (core/StepBatches.h).
using BatchStepper = void (*)(Component* const* components, std::size_t count, double time);
// The batch step of a type without its own: one virtual call per component.
void stepVirtually(Component* const* components, std::size_t count, double time);

enum class CqsKind { C, Q, S, Undefined };
const char* cqsKindName(CqsKind kind);

enum class MessageType { Info, Warning, Error, Fatal, Debug };

struct Message {
    MessageType type;
    std::string text;
    std::string tag;
    std::string source = {};   // model path of the component that reported it ("Sub$Comp")
    StatusCode code = StatusCode::Ok;   // of an error, where the reporter gives one
};

class Component {
public:
    explicit Component(CqsKind kind);
    virtual ~Component();
    Component(const Component&) = delete;
    Component& operator=(const Component&) = delete;

    // --- life cycle (called by the system) ---
    virtual void configure() {}
    virtual void preInitialize() {}
    virtual void initialize() {}
    virtual void simulateOneTimestep() {}
    virtual void finalize() {}
    // A component whose ports and parameters come from outside the model file (an imported
    // FMU names them) declares them here. Whoever builds a model calls it once the
    // component is in its system with its own parameters set, and before connecting it:
    // the .hmf loader, the model copy and model editing (after a parameter change).
    virtual Status loadExternalDefinition() { return Status::ok(); }
    // True for a component whose loadExternalDefinition reads files (an FMU unpacked and
    // parsed): a model from a user may hold only a bounded number (LoadLimits).
    virtual bool loadsExternalDefinition() const { return false; }
    // Not virtual: the step loop asks this of every component every step.
    bool isSystem() const { return mIsSystem; }
    // The batch step of this component's type: TLMHUB_REGISTER_COMPONENT sets a direct one,
    // a subsystem its own; anything else steps by its virtual call.
    BatchStepper batchStepper() const { return mBatchStepper; }
    void setBatchStepper(BatchStepper step) { mBatchStepper = step; }

    // --- identity ---
    const std::string& name() const { return mName; }
    void setNameRaw(std::string name) { mName = std::move(name); }
    const std::string& typeName() const { return mTypeName; }
    void setTypeName(std::string t) { mTypeName = std::move(t); }
    const std::string& subTypeName() const { return mSubTypeName; }
    void setSubTypeName(std::string t) { mSubTypeName = std::move(t); }
    virtual CqsKind kind() const { return mKind; }
    System* parentSystem() const { return mParent; }
    void setParentSystem(System* s) { mParent = s; }
    bool isDisabled() const { return mDisabled; }
    void setDisabled(bool d) { mDisabled = d; }
    // Depth below the root (root = 0).
    int depth() const;
    // "Sub$Comp": the names from below the root down to this one (empty for the root).
    std::string modelPath() const;

    // --- ports ---
    Port* port(const std::string& name) const;
    // Ports in byte-wise name order (the order Hopsan iterates them).
    const std::map<std::string, Port*>& portsByName() const { return mPortsByName; }
    // Ports in declaration order.
    std::vector<Port*> ports() const;
    bool renamePort(const std::string& oldName, const std::string& newName);
    Port* addPortRaw(std::unique_ptr<Port> port);
    bool removePort(const std::string& name);

    // --- parameters ---
    ParameterSet& parameters() { return mParameters; }
    const ParameterSet& parameters() const { return mParameters; }

    // Bind input/output variable pointers to the current nodes (before initialize).
    void bindAutoVariables();

    // --- time (mTime and mTimestep are declared last, see there) ---
    double time() const { return mTime; }
    double timestep() const { return mTimestep; }
    virtual void setTimestep(double ts) { mTimestep = ts; }

    // --- messages and stopping ---
    void addMessage(MessageType type, const std::string& text, const std::string& tag = {});
    void addInfoMessage(const std::string& t) { addMessage(MessageType::Info, t); }
    void addWarningMessage(const std::string& t) { addMessage(MessageType::Warning, t); }
    void addErrorMessage(const std::string& t) { addMessage(MessageType::Error, t); }
    void addDebugMessage(const std::string& t) { addMessage(MessageType::Debug, t); }
    // Ask the root system to stop the running simulation (reported as failure).
    void stopSimulation(const std::string& reason = {});
    // End the run at this step as the model designs it (Hopsan's SignalStopSimulation): the
    // run reports SimulationEnded with this reason, a normal finish, unless a component
    // reported an error.
    void endSimulation(const std::string& reason);
    // Directory of the model file (for components reading data files).
    std::string modelDirectory() const;
    // The simulation's random numbers (for noise sources; bind it in initialize()). The root
    // reseeds it at every start; a model that draws from it runs on one thread, in list order.
    RandomStream& randomStream();
    // Resolve a possibly relative path against the model directory.
    // Empty (with an error message) when model file access is off (core/FileAccess.h).
    std::string findFilePath(const std::string& path);

    // Catalogue metadata (filled by the factory).
    std::string libraryDomain;

    // Where the GUI draws it; saved into the <hopsangui> that preservedXml holds.
    ObjectLayout layout;
    // Model-file content the core does not interpret (GUI data such as <hopsangui>),
    // serialized XML of the element's other children, written back on save with only the
    // layout values that changed rewritten (core/GuiLayout.h says why).
    std::string preservedXml;

protected:
    bool mIsSystem = false;   // set by System's constructor
    BatchStepper mBatchStepper = &stepVirtually;

    // --- port registration ---
    Port* addPowerPort(const std::string& name, NodeType type, bool required = true);
    Port* addReadPort(const std::string& name, NodeType type, bool required = true);
    Port* addWritePort(const std::string& name, NodeType type, bool required = false);
    Port* addPowerMultiPort(const std::string& name, NodeType type, bool required = true);
    Port* addReadMultiPort(const std::string& name, NodeType type, bool required = false);
    // A signal port the component both reads and writes (different slots, or a direction
    // chosen at initialise). No start node and no sort hint unless the component sets one.
    Port* addBiDirectionalSignalPort(const std::string& name, NodeType type, bool required = false);

    // Input variable: an optional signal read port `name` whose value, when unconnected,
    // is the parameter `name#Value` (default `defaultValue`). *data is bound to the node.
    Port* addInputVariable(const std::string& name, const std::string& description,
                           const std::string& unit, double defaultValue, double** data);
    // Output variable without start value parameter (node starts at 0).
    Port* addOutputVariable(const std::string& name, const std::string& description,
                            const std::string& unit, double** data);
    // Output variable with a start value parameter `name#Value`.
    Port* addOutputVariable(const std::string& name, const std::string& description,
                            const std::string& unit, double defaultValue, double** data);

    // Whether the start values of these signal variables ("y_A" for y_A#Value) may change
    // while the simulation runs (Parameter::liveChangeable). An input variable may by
    // default, as its node is read every step; a type that reads one only in initialize()
    // says no, a source whose output node holds its constant says yes.
    void setLiveChangeable(std::initializer_list<std::string_view> variables, bool changeable);

    // --- constants ---
    void addConstant(const std::string& name, const std::string& description,
                     const std::string& unit, double defaultValue, double& variable);
    void addConstant(const std::string& name, const std::string& description,
                     const std::string& unit, int defaultValue, int& variable);
    void addConstant(const std::string& name, const std::string& description, bool defaultValue,
                     bool& variable);
    void addConstant(const std::string& name, const std::string& description,
                     const std::string& defaultValue, std::string& variable,
                     ParameterType type = ParameterType::String);
    void addConditionalConstant(const std::string& name, const std::string& description,
                                std::vector<std::string> alternatives, int defaultIndex,
                                int& variable);

    // --- start values ---
    void setDefaultStartValue(Port* port, int id, double value);
    void disableStartValue(Port* port, int id);
    double getDefaultStartValue(const Port* port, int id) const;

    // --- node access for initialize() ---
    // Pointer to slot `id` of the port's node (a multiport: of its first sub-port, or a
    // zero dummy when it has none).
    double* getSafeNodeDataPtr(Port* port, int id);
    double* getSafeMultiPortNodeDataPtr(Port* port, std::size_t subIndex, int id);
    // The same, and writes `initialValue` into that slot first (Hopsan's four-argument
    // form; e.g. a cylinder block zeroes its piston nodes, overriding their start values).
    double* getSafeMultiPortNodeDataPtr(Port* port, std::size_t subIndex, int id, double initialValue);
    // Number of sub-ports of a multiport (connections), 1 for other ports.
    std::size_t getNumPorts(const Port* port) const;

private:
    Port* addPortInternal(const std::string& name, PortKind kind, NodeType type, bool required);
    void registerStartValueParameters(Port* port);

    struct AutoBinding {
        Port* port;
        double** data;
    };

    std::string mName;
    std::string mTypeName;
    std::string mSubTypeName;
    CqsKind mKind;
    System* mParent = nullptr;
    bool mDisabled = false;
    std::vector<std::unique_ptr<Port>> mPorts;
    std::map<std::string, Port*> mPortsByName;
    ParameterSet mParameters;
    std::vector<AutoBinding> mAutoBindings;
    double mDummy[32] = {};

public:
    // Declared last so that they share a cache line with the first members of the component
    // type: a step touches them and its type's own state, not the cold data above.
    double mTime = 0.0;
    double mTimestep = 0.001;
};

class ComponentC : public Component {
public:
    ComponentC() : Component(CqsKind::C) {}
};

class ComponentQ : public Component {
public:
    ComponentQ() : Component(CqsKind::Q) {}
};

class ComponentSignal : public Component {
public:
    ComponentSignal() : Component(CqsKind::S) {}
};

} // namespace tlmhub
