#pragma once
// The editable JSON view of a model (ModelJson in protocol/messages.schema.json): systems,
// components with ports, parameters and GUI poses, and connections with their line points.
// Names and kinds are the ones the catalogue (core/Catalogue.cpp) and .hmf files use.
#include "core/System.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace tlmhub::server {

nlohmann::json modelToJson(const System& root, const std::string& modelName);
nlohmann::json componentToJson(const Component& component);
nlohmann::json systemToJson(const System& system);
// The root's own times and log samples (SimulationSettings).
nlohmann::json simulationSettingsToJson(const System& root);
nlohmann::json parameterToJson(const Parameter& parameter);      // Param
nlohmann::json systemParameterToJson(const Parameter& parameter); // SysParam

// One connection made in a system, each end named as .hmf names it: a system port of the
// system itself has its own name as component and port.
struct ConnectionEnds {
    std::string fromComponent, fromPort, toComponent, toPort;
};

// Every connection made inside `system` (not those of its subsystems), each once, in the
// order the model file lists them.
std::vector<ConnectionEnds> connectionsOf(const System& system);
// The connection's GUI extras (line points) stored for it in either direction, or null;
// `reversed` tells that they were stored as to -> from (their points run that way).
const std::string* preservedConnectionXml(const System& system, const ConnectionEnds& ends, bool& reversed);
nlohmann::json connectionToJson(const System& system, const ConnectionEnds& ends);

} // namespace tlmhub::server
