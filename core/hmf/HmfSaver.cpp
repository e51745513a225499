#include "core/hmf/HmfSaver.h"

#include "core/SystemConnections.h"
#include "core/hmf/GuiLayoutXml.h"
#include "core/hmf/PreservedXml.h"

#include <pugixml.hpp>

#include <fstream>
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
    guixml::writeObjectLayout(e, c.layout);
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
    guixml::writeObjectLayout(e, s.layout);
    if (isRoot) guixml::writeLiveControls(e, s.liveControls);

    pugi::xml_node objects = e.append_child("objects");
    for (Component* c : s.componentsInOrder()) writeComponent(objects, *c);
    for (Port* p : s.ports()) {
        if (p->kind() != PortKind::System) continue;
        pugi::xml_node sp = objects.append_child("systemport");
        sp.append_attribute("name") = p->name().c_str();
        sp.append_attribute("typename") = "HopsanGUIContainerPort";
        auto it = s.systemPortExtras.find(p->name());
        if (it == s.systemPortExtras.end()) continue;
        preserved::appendFragment(sp, it->second.preservedXml);
        guixml::writeObjectLayout(sp, it->second.layout);
    }
    for (const std::string& other : s.preservedObjectsXml) preserved::appendFragment(objects, other);

    pugi::xml_node conns = e.append_child("connections");
    forEachConnection(s, [&conns](const SystemConnection& connection) {
        pugi::xml_node c = conns.append_child("connect");
        c.append_attribute("startcomponent") = connection.startComponent.c_str();
        c.append_attribute("startport") = connection.startPort.c_str();
        c.append_attribute("endcomponent") = connection.endComponent.c_str();
        c.append_attribute("endport") = connection.endPort.c_str();
        if (!connection.extras) return;
        preserved::appendFragment(c, connection.extras->preservedXml);
        guixml::writeConnectionLayout(c, connection.extras->layout);
    });
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
