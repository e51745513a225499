#include "server/edit/EditSession.h"

#include "core/ComponentFactory.h"
#include "core/ParameterEvaluator.h"
#include "core/ParameterPath.h"
#include "core/hmf/HmfLoader.h"
#include "core/hmf/PreservedXml.h"
#include "server/api/CoreErrorCodes.h"
#include "server/edit/ModelJson.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>

namespace tlmhub::server {

namespace {

using nlohmann::json;
using Result = EditSession::Result;

Result fail(std::string code, std::string message)
{
    Result r;
    r.ok = false;
    r.code = std::move(code);
    r.message = std::move(message);
    return r;
}

Result fail(StatusCode code, std::string message) { return fail(protocolErrorCode(code), std::move(message)); }
Result fail(const Status& status) { return fail(status.code(), status.message()); }

Result success(json data = json::object())
{
    Result r;
    r.data = std::move(data);
    return r;
}

// A parameter value as the model stores it: strings as given, numbers in the shortest
// form that reads back as the same double.
std::string valueString(const json& value)
{
    if (value.is_string()) return value.get<std::string>();
    if (value.is_number_integer()) return std::to_string(value.get<std::int64_t>());
    if (value.is_number()) return formatNumber(value.get<double>());
    throw std::invalid_argument("value: expected string or number");
}

ConnectionEnds endsOf(const protocol::PortRef& from, const protocol::PortRef& to)
{
    return {from.component, from.port, to.component, to.port};
}

Pose guiPose(const protocol::Pose& pose)
{
    return {.x = pose.x, .y = pose.y, .angle = pose.angle, .flipped = pose.flipped};
}

// A handler of the request type Request; the JSON is decoded once it is known to be one.
template <typename Request>
auto decoding(Result (EditSession::*handler)(System&, const Request&))
{
    return [handler](EditSession& session, System& system, const json& request) {
        return (session.*handler)(system, request.get<Request>());
    };
}

void eraseConnectionExtras(System& system, const ConnectionEnds& e)
{
    system.connectionExtras.erase(preserved::connectionKey(e.fromComponent, e.fromPort, e.toComponent, e.toPort));
    system.connectionExtras.erase(preserved::connectionKey(e.toComponent, e.toPort, e.fromComponent, e.fromPort));
}

} // namespace

// ---------------------------------------------------------------- open / save

bool EditSession::openHmf(const std::string& hmf, const std::string& name, std::string& error)
{
    try {
        LoadedModel loaded = loadHmfString(hmf, std::string(), name.empty() ? "<model>" : name);
        if (!loaded.root) {
            error = loaded.firstError().empty() ? "the model could not be loaded" : loaded.firstError();
            return false;
        }
        mModel.emplace(std::move(loaded.root));
        mLoadMessages = std::move(loaded.messages);
        mName = name;
        return true;
    } catch (const std::exception& e) {
        error = std::string("the model could not be loaded: ") + e.what();
        return false;
    }
}

void EditSession::createEmpty(const std::string& name)
{
    mModel.emplace();
    mModel->root().setNameRaw(sanitizeName(name));
    mLoadMessages.clear();
    mName = name;
}

void EditSession::close()
{
    mModel.reset();
    mLoadMessages.clear();
    mName.clear();
}

std::string EditSession::saveHmf() const
{
    return mModel ? mModel->toHmf() : std::string();
}

protocol::Model EditSession::model() const
{
    return describeModel(mModel->root(), mName);
}

// ---------------------------------------------------------------- dispatch

Result EditSession::handle(const json& request)
{
    using Handler = std::function<Result(EditSession&, System&, const json&)>;
    static const std::map<std::string, Handler> handlers = {
        {"component.add", decoding(&EditSession::componentAdd)},
        {"component.remove", decoding(&EditSession::componentRemove)},
        {"component.rename", decoding(&EditSession::componentRename)},
        {"component.move", decoding(&EditSession::componentMove)},
        {"connect", decoding(&EditSession::connect)},
        {"disconnect", decoding(&EditSession::disconnect)},
        {"connection.route", decoding(&EditSession::connectionRoute)},
        {"parameter.get", decoding(&EditSession::parameterGet)},
        {"parameter.set", decoding(&EditSession::parameterSet)},
        {"sysparam.set", decoding(&EditSession::sysparamSet)},
        {"sysparam.remove", decoding(&EditSession::sysparamRemove)},
        {"model.settings", decoding(&EditSession::modelSettings)},
        {"model.controls", decoding(&EditSession::modelControls)},
        {"model.group", decoding(&EditSession::modelGroup)},
        {"model.ungroup", decoding(&EditSession::modelUngroup)},
    };
    try {
        if (!request.is_object()) return fail("bad_request", "a request must be a JSON object");
        const std::string type = request.at("type").get<std::string>();
        auto handler = handlers.find(type);
        if (type != "model.get" && handler == handlers.end())
            return fail("unknown_message_type", "the model editor does not handle \"" + type + "\"");
        if (!isOpen()) return fail("not_open", "no model is open");
        if (type == "model.get") return modelGet();
        Result failure;
        System* system = targetSystem(request, failure);
        if (!system) return failure;
        return handler->second(*this, *system, request);
    } catch (const json::exception& e) {
        return fail("bad_request", std::string("malformed request: ") + e.what());
    } catch (const std::invalid_argument& e) {
        return fail("bad_request", e.what());
    } catch (const std::exception& e) {
        return fail("internal", e.what());
    }
}

System* EditSession::targetSystem(const json& request, Result& failure)
{
    System* system = &mModel->root();
    auto path = request.find("system");
    if (path == request.end() || path->is_null()) return system;
    if (!path->is_array()) {
        failure = fail("bad_request", "system: expected an array of subsystem names");
        return nullptr;
    }
    for (const json& step : *path) {
        const std::string name = step.get<std::string>();
        System* sub = system->subsystem(name);
        if (!sub) {
            failure = fail("not_found", "no subsystem '" + name + "' in system '" + system->name() + "'");
            return nullptr;
        }
        system = sub;
    }
    return system;
}

Result EditSession::modelGet()
{
    return success(protocol::ModelGetData{.model = model()});
}

// ---------------------------------------------------------------- components

Result EditSession::componentAdd(System& system, const protocol::ComponentAddRequest& request)
{
    const std::string& type = request.componentType;
    std::unique_ptr<Component> component;
    if (type == "Subsystem" || type == "ConditionalSubsystem") {
        auto sub = std::make_unique<System>();
        if (type == "ConditionalSubsystem") sub->makeConditional();
        sub->setNameRaw(type);
        component = std::move(sub);
    } else {
        component = ComponentFactory::instance().create(type);
    }
    if (!component) return fail("unknown_component_type", "unknown component type '" + type + "'");
    if (request.name) component->setNameRaw(*request.name);
    if (request.pose) component->layout.pose = guiPose(*request.pose);
    Component* added = component.get();
    system.addComponent(std::move(component));
    return success(protocol::ComponentAddedData{.component = describeComponent(*added)});
}

Result EditSession::componentRemove(System& system, const protocol::ComponentRemoveRequest& request)
{
    const std::string& name = request.name;
    if (const Status removed = system.removeComponent(name); !removed) return fail(removed);
    // Drop what was kept for its connections and aliases, so a later component of the same
    // name does not inherit them.
    for (auto it = system.connectionExtras.begin(); it != system.connectionExtras.end();) {
        const preserved::ConnectionKeyParts k = preserved::parseConnectionKey(it->first);
        it = (k.a == name || k.b == name) ? system.connectionExtras.erase(it) : std::next(it);
    }
    for (auto it = system.aliases.begin(); it != system.aliases.end();)
        it = it->second.rfind(name + "#", 0) == 0 ? system.aliases.erase(it) : std::next(it);
    return success();
}

Result EditSession::componentRename(System& system, const protocol::ComponentRenameRequest& request)
{
    const std::string& name = request.name;
    const auto renamed = system.renameComponent(name, request.newName);
    if (!renamed) return fail(renamed.status());
    const std::string& actual = *renamed;
    if (actual != name) {
        // Connection extras and aliases are keyed by component name.
        std::map<std::string, ConnectionExtras> rekeyed;
        auto renamedEnd = [&](const std::string& end) { return end == name ? actual : end; };
        for (auto& [key, extras] : system.connectionExtras) {
            const preserved::ConnectionKeyParts k = preserved::parseConnectionKey(key);
            rekeyed[preserved::connectionKey(renamedEnd(k.a), k.pa, renamedEnd(k.b), k.pb)] = std::move(extras);
        }
        system.connectionExtras = std::move(rekeyed);
        for (auto& [alias, full] : system.aliases)
            if (full.rfind(name + "#", 0) == 0) full = actual + full.substr(name.size());
    }
    return success(protocol::ComponentRenamedData{.name = actual});
}

Result EditSession::componentMove(System& system, const protocol::ComponentMoveRequest& request)
{
    const std::string& name = request.name;
    const Pose pose = guiPose(request.pose);
    if (Component* c = system.component(name)) {
        c->layout.pose = pose;
        return success();
    }
    if (system.systemPort(name)) {
        system.systemPortExtras[name].layout.pose = pose;
        return success();
    }
    return fail("not_found", "no component or system port named '" + name + "' in system '" + system.name() + "'");
}

// ---------------------------------------------------------------- connections

Result EditSession::connect(System& system, const protocol::ConnectRequest& request)
{
    const ConnectionEnds e = endsOf(request.from, request.to);
    if (const Status connected = system.connect(e.fromComponent, e.fromPort, e.toComponent, e.toPort); !connected)
        return fail(connected);
    eraseConnectionExtras(system, e);
    if (request.points && !request.points->empty()) {
        std::vector<LinePoint>& points =
            system.connectionExtras[preserved::connectionKey(e.fromComponent, e.fromPort, e.toComponent, e.toPort)]
                .layout.points;
        for (const std::vector<double>& p : *request.points) points.push_back({p.at(0), p.at(1)});
    }
    return success(protocol::ConnectedData{.connection = describeConnection(system, e)});
}

Result EditSession::disconnect(System& system, const protocol::DisconnectRequest& request)
{
    const ConnectionEnds e = endsOf(request.from, request.to);
    if (const Status disconnected = system.disconnect(e.fromComponent, e.fromPort, e.toComponent, e.toPort);
        !disconnected)
        return fail(disconnected);
    eraseConnectionExtras(system, e);
    return success();
}

Result EditSession::connectionRoute(System& system, const protocol::ConnectionRouteRequest& request)
{
    const ConnectionEnds e = endsOf(request.from, request.to);
    const std::vector<ConnectionEnds> existing = connectionsOf(system);
    const bool connected = std::any_of(existing.begin(), existing.end(), [&e](const ConnectionEnds& c) {
        return (c.fromComponent == e.fromComponent && c.fromPort == e.fromPort && c.toComponent == e.toComponent &&
                c.toPort == e.toPort) ||
               (c.fromComponent == e.toComponent && c.fromPort == e.toPort && c.toComponent == e.fromComponent &&
                c.toPort == e.fromPort);
    });
    if (!connected)
        return fail("not_found", e.fromComponent + "." + e.fromPort + " and " + e.toComponent + "." + e.toPort +
                                     " are not connected in system '" + system.name() + "'");
    for (const std::vector<double>& p : request.points)
        if (!std::isfinite(p.at(0)) || !std::isfinite(p.at(1)))
            return fail("bad_request", "points: every coordinate must be a finite number");
    // The points go where the connection's extras already are (kept in the order of the file's
    // ends), so what else the file kept for the line stays with it.
    bool reversed = false;
    const std::string key = connectionExtrasKey(system, e, reversed);
    std::vector<LinePoint> points;
    for (const std::vector<double>& p : request.points) points.push_back({p.at(0), p.at(1)});
    if (reversed) std::reverse(points.begin(), points.end());
    system.connectionExtras[key].layout.points = std::move(points);
    return success(protocol::ConnectedData{.connection = describeConnection(system, e)});
}

// ---------------------------------------------------------------- parameters

Result EditSession::parameterGet(System& system, const protocol::ParameterGetRequest& request)
{
    const std::string& compName = request.component;
    const std::string& paramName = request.parameter;
    Component* c = system.component(compName);
    if (!c) return fail("not_found", "no component named '" + compName + "' in system '" + system.name() + "'");
    const Parameter* p = c->parameters().find(paramName);
    if (!p) return fail("not_found", "component '" + compName + "' has no parameter '" + paramName + "'");
    return success(protocol::ParameterData{.parameter = describeParameter(*p)});
}

Result EditSession::parameterSet(System& system, const protocol::ParameterSetRequest& request)
{
    const std::string& compName = request.component;
    const std::string& paramName = request.parameter;
    const std::string value = valueString(request.value);
    Component* c = system.component(compName);
    if (!c) return fail("not_found", "no component named '" + compName + "' in system '" + system.name() + "'");
    Parameter* p = c->parameters().find(paramName);
    if (!p) return fail("not_found", "component '" + compName + "' has no parameter '" + paramName + "'");
    if (const Status assigned = assignParameter(*c, *p, value); !assigned)
        return fail(assigned.code(), compName + "." + paramName + ": " + assigned.message());
    return success(protocol::ParameterData{.parameter = describeParameter(*p)});
}

Result EditSession::sysparamSet(System& system, const protocol::SysParamSetRequest& request)
{
    const std::string& name = request.name;
    const std::string value = valueString(request.value);
    const Parameter* existing = system.parameters().find(name);
    const std::optional<Parameter> before =
        existing ? std::optional<Parameter>(*existing) : std::optional<Parameter>();
    const std::string type = request.paramType.value_or(existing ? parameterTypeName(existing->type) : "double");
    const std::string unit = request.unit.value_or(existing ? existing->unit : std::string());
    const std::string description = request.description.value_or(existing ? existing->description : std::string());
    const bool internal = existing && existing->internal;

    if (const Status set = system.setSystemParameter(name, value, type, description, unit, internal); !set)
        return fail(set);
    Parameter* p = system.parameters().find(name);
    if (!p) return fail("internal", "system parameter '" + name + "' vanished after setting it");
    Status evaluated = ParameterEvaluator::evaluate(system, *p);
    if (evaluated) evaluated = finiteValueStatus(*p);
    if (!evaluated) {
        if (before) {
            system.setSystemParameter(name, before->value, parameterTypeName(before->type), before->description,
                                      before->unit, before->internal);
            if (Parameter* restored = system.parameters().find(name)) ParameterEvaluator::evaluate(system, *restored);
        } else {
            system.removeSystemParameter(name);
        }
        return fail(evaluated.code(), name + ": " + evaluated.message());
    }
    return success(protocol::SysParamData{.parameter = describeSystemParameter(*p)});
}

Result EditSession::sysparamRemove(System& system, const protocol::SysParamRemoveRequest& request)
{
    const std::string& name = request.name;
    if (!system.removeSystemParameter(name))
        return fail("not_found", "no system parameter '" + name + "' in system '" + system.name() + "'");
    return success();
}

// The root's own simulation settings (a subsystem path, if given, is ignored: subsystems
// share the root's times).
Result EditSession::modelSettings(System&, const protocol::ModelSettingsRequest& request)
{
    System& root = mModel->root();
    const double start = request.start.value_or(root.startTime);
    const double step = request.step.value_or(root.desiredTimestep);
    const double stop = request.stop.value_or(root.stopTime);
    if (!(std::isfinite(start) && std::isfinite(stop) && std::isfinite(step)) || step <= 0 || stop < start)
        return fail("bad_request", "simulation settings need finite times, step > 0 and stop >= start");
    root.startTime = start;
    root.desiredTimestep = step;
    root.stopTime = stop;
    if (request.logSamples) root.requestedLogSamples = static_cast<std::size_t>(*request.logSamples);
    return success(protocol::ModelSettingsData{.simulation = describeSimulationSettings(root)});
}

// The root's live controls, all at once (a subsystem path, if given, is ignored: each control
// names the drawing it is on). Saved in the model's GUI data (core/GuiLayout.h).
Result EditSession::modelControls(System&, const protocol::ModelControlsRequest& request)
{
    static const std::set<std::string> kinds = {"slider", "knob", "switch", "number"};
    std::vector<LiveControlLayout> controls;
    for (std::size_t i = 0; i < request.controls.size(); ++i) {
        const LiveControlLayout c = liveControlOf(request.controls[i]);
        const std::string which = "controls[" + std::to_string(i) + "]";
        if (!kinds.contains(c.kind)) return fail("bad_request", which + ".kind: expected slider, knob, switch or number");
        const bool finite = std::isfinite(c.min) && std::isfinite(c.max) && std::isfinite(c.x) && std::isfinite(c.y)
                            && std::isfinite(c.off.value_or(0)) && std::isfinite(c.on.value_or(0));
        if (!finite) return fail("bad_request", which + ": every number must be finite");
        controls.push_back(c);
    }
    System& root = mModel->root();
    root.liveControls = std::move(controls);
    protocol::ModelControlsData data;
    for (const LiveControlLayout& c : root.liveControls) data.controls.push_back(describeLiveControl(c));
    return success(data);
}

// ---------------------------------------------------------------- grouping

Result EditSession::modelGroup(System& system, const protocol::ModelGroupRequest& request)
{
    const std::vector<std::string>& names = request.names;
    // The subsystem goes where the grouped components were, unless the request places it.
    Pose pose;
    if (request.pose) {
        pose = guiPose(*request.pose);
    } else {
        std::size_t found = 0;
        for (const std::string& n : names)
            if (const Component* c = system.component(n)) {
                const Pose& p = c->layout.pose;
                pose.x += p.x;
                pose.y += p.y;
                ++found;
            }
        if (found > 0) {
            pose.x /= static_cast<double>(found);
            pose.y /= static_cast<double>(found);
        }
    }
    const auto grouped = system.group(names, request.name);
    if (!grouped) return fail(grouped.status());
    system.component(*grouped)->layout.pose = pose;
    return success(protocol::ModelGroupedData{.name = *grouped});
}

Result EditSession::modelUngroup(System& system, const protocol::ModelUngroupRequest& request)
{
    const auto moved = system.ungroup(request.name);
    if (!moved) return fail(moved.status());
    return success(protocol::ModelUngroupedData{.names = *moved});
}

} // namespace tlmhub::server
