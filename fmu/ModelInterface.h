#pragma once
// Which variables a model offers when it is exported as an FMU (the interface rules):
//  - each root-level SignalInputInterface is a real input, each SignalOutputInterface a
//    real output, named after the component;
//  - each root-level <Domain>InterfaceC / <Domain>InterfaceQ is a power port: its node's
//    TLM slots (wave variable, characteristic impedance) go one way, the node's other
//    visible slots (effort, flow, position...) the other; the variables are named
//    "<component>.<slot short name>" ("P1.c", "P1.Zc", "P1.p", "P1.q");
//    a C-type interface takes c and Zc as inputs, a Q-type one takes the others;
//  - the root system's real parameters and the component parameters the caller names
//    ("Comp.param") are parameters (causality parameter, variability fixed: they apply
//    from initialisation on); their values must be numbers, not expressions (a system
//    parameter of another type has no FMI 2.0 real form and is left out);
//  - "tlmhub.timestep" is a fixed parameter: the model's step (default the model's own).
// Value references count from 0 in that order: inputs, outputs, parameters, timestep.
#include "core/Model.h"
#include "core/Status.h"
#include "core/System.h"
#include "fmu/ModelDescription.h"

#include <string>
#include <vector>

namespace tlmhub::fmu {

struct InterfaceOptions {
    std::vector<std::string> parameters;   // component parameter paths to offer ("Mass.m")
    std::string modelIdentifier;           // default: from the model name
};

// How the runtime reaches one variable of the description (same index).
struct VariableBinding {
    enum class Kind { NodeSlot, Parameter, Timestep } kind = Kind::NodeSlot;
    std::string component;       // root-level interface component (NodeSlot)
    std::string port;            // its port (NodeSlot)
    int slot = 0;                // node data slot (NodeSlot)
    std::string parameterPath;   // Parameter: as Simulation::setParameter takes it
};

struct ModelInterface {
    ModelDescription description;   // variables, ModelStructure outputs, power ports, experiment
    std::vector<VariableBinding> bindings;
};

Result<ModelInterface> describeInterface(const System& root, const InterfaceOptions& options = {});

// Sets each input's start to the value its node slot has once the model is initialised
// (start values, the TLM copy rule applied), so that an FMU whose inputs are left alone
// computes what a run of the model does. Compiles and initialises a copy of `model`: its
// failure (the model does not compile or initialise) is returned.
Status takeInputStartsFromInitialisation(ModelInterface& modelInterface, const Model& model);

} // namespace tlmhub::fmu
