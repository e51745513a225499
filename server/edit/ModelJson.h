#pragma once
// The editable view of a model (Model in protocol/messages.schema.json): systems,
// components with ports, parameters and GUI poses, and connections with their line points.
// Built as the structs generated from the schema, so what the server sends cannot drift
// from what the schema says. Names and kinds are the ones the catalogue
// (core/Catalogue.cpp) and .hmf files use.
#include "core/System.h"
#include "server/protocol/Messages.generated.h"

#include <string>
#include <vector>

namespace tlmhub::server {

protocol::Model describeModel(const System& root, const std::string& modelName);
protocol::Component describeComponent(const Component& component);
protocol::System describeSystem(const System& system);
// The root's own times and log samples.
protocol::SimulationSettings describeSimulationSettings(const System& root);
protocol::Param describeParameter(const Parameter& parameter);
protocol::LiveControl describeLiveControl(const LiveControlLayout& control);
// The control a request describes (the schema checked its fields' types).
LiveControlLayout liveControlOf(const protocol::LiveControl& control);
protocol::SysParam describeSystemParameter(const Parameter& parameter);

// One connection made in a system, each end named as .hmf names it: a system port of the
// system itself has its own name as component and port.
struct ConnectionEnds {
    std::string fromComponent, fromPort, toComponent, toPort;
};

// Every connection made inside `system` (not those of its subsystems), each once, in the
// order the model file lists them.
std::vector<ConnectionEnds> connectionsOf(const System& system);
// The key of the connection's extras in system.connectionExtras: the one stored in either
// order of its ends (`reversed`: stored as to -> from), else the key of its own order.
std::string connectionExtrasKey(const System& system, const ConnectionEnds& ends, bool& reversed);
// The connection's layout (line points) stored for it in either direction, or null;
// `reversed` tells that it was stored as to -> from (its points run that way).
const ConnectionLayout* connectionLayout(const System& system, const ConnectionEnds& ends, bool& reversed);
protocol::Connection describeConnection(const System& system, const ConnectionEnds& ends);

} // namespace tlmhub::server
