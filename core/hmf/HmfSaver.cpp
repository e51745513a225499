#include "core/hmf/HmfSaver.h"

#include "core/hmf/PreservedXml.h"

#include <pugixml.hpp>

#include <fstream>
#include <set>
#include <sstream>

namespace tlmhub {

namespace {

void writeParameters(pugi::xml_node parent, const Component& c, bool systemParameters)
{
    pugi::xml_node params = parent.append_child("parameters");
    for (const auto& p : c.parameters().all()) {
        if (systemParameters && p->isStartValue) continue;
        pugi::xml_node e = params.append_child("parameter");
        e.append_attribute("name") = p->name.c_str();
        e.append_attribute("value") = p->value.c_str();
        e.append_attribute("type") = parameterTypeName(p->type);
        if (!p->unit.empty()) e.append_attribute("unit") = p->unit.c_str();
        if (systemParameters) {
            if (!p->description.empty()) e.append_attribute("description") = p->description.c_str();
            if (p->internal) e.append_attribute("internal") = "true";
        }
    }
}

void writeStartValueParameters(pugi::xml_node params, const System& s)
{
    for (const auto& p : s.parameters().all()) {
        if (!p->isStartValue) continue;
        pugi::xml_node e = params.append_child("parameter");
        e.append_attribute("name") = p->name.c_str();
        e.append_attribute("value") = p->value.c_str();
        e.append_attribute("type") = "double";
    }
}

void writeSystem(pugi::xml_node e, const System& s, bool isRoot);

void writeComponent(pugi::xml_node objects, const Component& c)
{
    if (c.isSystem()) {
        const auto& s = static_cast<const System&>(c);
        pugi::xml_node e = objects.append_child("system");
        writeSystem(e, s, false);
        return;
    }
    pugi::xml_node e = objects.append_child("component");
    e.append_attribute("name") = c.name().c_str();
    e.append_attribute("typename") = c.typeName().c_str();
    e.append_attribute("subtypename") = c.subTypeName().c_str();
    e.append_attribute("cqstype") = cqsKindName(c.kind());
    e.append_attribute("disabled") = c.isDisabled() ? "true" : "false";
    writeParameters(e, c, false);
    preserved::appendFragment(e, c.preservedXml);
}

void writeSystem(pugi::xml_node e, const System& s, bool isRoot)
{
    e.append_attribute("name") = s.name().c_str();
    e.append_attribute("typename") = s.isConditional() ? "ConditionalSubsystem" : "Subsystem";
    e.append_attribute("subtypename") = s.subTypeName().c_str();
    e.append_attribute("cqstype") = cqsKindName(s.kind());
    e.append_attribute("disabled") = s.isDisabled() ? "true" : "false";
    if (!s.externalPath.empty()) {
        e.append_attribute("external_path") = s.externalPath.c_str();
        writeParameters(e, s, true);
        return;
    }
    pugi::xml_node st = e.append_child("simulationtime");
    st.append_attribute("start") = isRoot ? s.startTime : 0.0;
    st.append_attribute("stop") = isRoot ? s.stopTime : 2.0;
    st.append_attribute("timestep") = s.desiredTimestep;
    st.append_attribute("inherit_timestep") = (isRoot || s.inheritTimestep) ? "true" : "false";
    pugi::xml_node ls = e.append_child("simulationlogsettings");
    ls.append_attribute("numsamples") = static_cast<unsigned long long>(s.requestedLogSamples);
    ls.append_attribute("starttime") = s.logStartTime;
    writeParameters(e, s, true);
    writeStartValueParameters(e.child("parameters"), s);
    pugi::xml_node aliases = e.append_child("aliases");
    for (const auto& [name, full] : s.aliases) {
        pugi::xml_node a = aliases.append_child("alias");
        a.append_attribute("type") = "variable";
        a.append_attribute("name") = name.c_str();
        a.append_child("fullname").text() = full.c_str();
    }
    preserved::appendFragment(e, s.preservedXml);

    pugi::xml_node objects = e.append_child("objects");
    for (Component* c : s.componentsInOrder()) writeComponent(objects, *c);
    for (Port* p : s.ports()) {
        if (p->kind() != PortKind::System) continue;
        pugi::xml_node sp = objects.append_child("systemport");
        sp.append_attribute("name") = p->name().c_str();
        sp.append_attribute("typename") = "HopsanGUIContainerPort";
        auto it = s.preservedSystemPortXml.find(p->name());
        if (it != s.preservedSystemPortXml.end()) preserved::appendFragment(sp, it->second);
    }
    for (const std::string& other : s.preservedObjectsXml) preserved::appendFragment(objects, other);

    // Each connection once: walk ports of sub-components and own system ports.
    pugi::xml_node conns = e.append_child("connections");
    std::set<std::pair<const Port*, const Port*>> written;
    auto nameOf = [&s](const Port* p) { return p->component() == &s ? p->name() : p->component()->name(); };
    auto emit = [&](const Port* a, const Port* b) {
        const Port* pa = a->parentMultiport ? a->parentMultiport : a;
        const Port* pb = b->parentMultiport ? b->parentMultiport : b;
        if (written.count({b, a}) || written.count({a, b})) return;
        // Only connections made in this system (both ends visible from here).
        auto visible = [&s](const Port* p) {
            return p->component() == &s || p->component()->parentSystem() == &s;
        };
        if (!visible(pa) || !visible(pb)) return;
        written.insert({a, b});
        // GUI extras (the line's points) were stored in the direction the file listed the
        // connection; write it in that direction so the points still run start to end.
        auto it = s.preservedConnectionXml.find(
            preserved::connectionKey(nameOf(pa), pa->name(), nameOf(pb), pb->name()));
        if (it == s.preservedConnectionXml.end()) {
            it = s.preservedConnectionXml.find(
                preserved::connectionKey(nameOf(pb), pb->name(), nameOf(pa), pa->name()));
            if (it != s.preservedConnectionXml.end()) std::swap(pa, pb);
        }
        pugi::xml_node c = conns.append_child("connect");
        c.append_attribute("startcomponent") = nameOf(pa).c_str();
        c.append_attribute("startport") = pa->name().c_str();
        c.append_attribute("endcomponent") = nameOf(pb).c_str();
        c.append_attribute("endport") = pb->name().c_str();
        if (it != s.preservedConnectionXml.end()) preserved::appendFragment(c, it->second);
    };
    // Connections in a stable order: by connection order of the ports.
    std::vector<const Port*> ports;
    for (Component* c : s.componentsInOrder())
        for (Port* p : c->ports()) {
            if (p->isMultiport()) for (const auto& sub : p->subPorts) ports.push_back(sub.get());
            else ports.push_back(p);
        }
    for (Port* p : s.ports())
        if (p->kind() == PortKind::System) ports.push_back(p);
    for (const Port* p : ports)
        for (const Port* q : p->connectedPorts) emit(p, q);
}

} // namespace

std::string saveHmfString(const System& root)
{
    pugi::xml_document doc;
    pugi::xml_node decl = doc.append_child(pugi::node_declaration);
    decl.append_attribute("version") = "1.0";
    decl.append_attribute("encoding") = "UTF-8";
    pugi::xml_node top = doc.append_child("hopsanmodelfile");
    top.append_attribute("hmfversion") = "0.4";
    top.append_attribute("hopsancoreversion") = "2.20.0";
    top.append_attribute("tlmhubversion") = "0.1.0";
    preserved::appendFragment(top, root.preservedDocumentXml);
    pugi::xml_node sys = top.append_child("system");
    writeSystem(sys, root, true);
    std::ostringstream os;
    doc.save(os, "  ");
    return os.str();
}

Status saveHmfFile(const System& root, const std::string& path)
{
    std::ofstream out(path, std::ios::binary);
    if (!out) return {StatusCode::IoError, "cannot write '" + path + "'"};
    out << saveHmfString(root);
    if (!out) return {StatusCode::IoError, "error writing '" + path + "'"};
    return Status::ok();
}

} // namespace tlmhub
