#pragma once
// The editable model: its root system with components, connections, system parameters and
// ports, subsystems, aliases, simulation settings, the GUI layout as typed values
// (core/GuiLayout.h) and the model-file content the core keeps without interpreting. Edits go
// through root() (System's editing API and its rules: unique names, connection rules naming
// both ports; layout fields are assigned directly).
//
// A run never touches a Model: compile(const Model&) builds the Simulation from a copy, so
// one Model compiles any number of times, on any number of threads at once, and stays as it
// was; compile(Model&&) hands the model over instead when the caller is done editing it.
//
//   Model model(std::move(loadHmfFile(path).root));
//   Result<Simulation> a = compile(model);              // a copy: `model` stays editable
//   Result<Simulation> b = compile(std::move(model));   // no copy
#include "core/Status.h"
#include "core/System.h"

#include <memory>
#include <string>

namespace tlmhub {

class Model {
public:
    Model();   // empty: a root system named after nothing
    explicit Model(std::unique_ptr<System> root);
    // A moved-from Model may only be assigned to or destroyed.
    Model(Model&&) noexcept = default;
    Model& operator=(Model&&) noexcept = default;
    Model(const Model&) = delete;
    Model& operator=(const Model&) = delete;

    System& root() { return *mRoot; }
    const System& root() const { return *mRoot; }

    // A deep copy (core/SystemCopy.h): the same as saving and reloading the model.
    Result<Model> copy() const;
    // The model as .hmf 0.4 text.
    std::string toHmf() const;
    // Gives up the root system (the model is empty afterwards).
    std::unique_ptr<System> releaseRoot();

private:
    std::unique_ptr<System> mRoot;
};

} // namespace tlmhub
