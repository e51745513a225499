#include "core/hmf/PreservedXml.h"

#include "core/System.h"
#include "core/hmf/GuiLayoutXml.h"

#include <set>
#include <sstream>

namespace tlmhub::preserved {

namespace {

std::string serializeChildrenExcept(pugi::xml_node element, const std::set<std::string>& skip)
{
    std::ostringstream os;
    for (pugi::xml_node child : element.children()) {
        if (child.type() == pugi::node_element && skip.count(child.name())) continue;
        child.print(os, "", pugi::format_raw);
    }
    return os.str();
}

} // namespace

void storeComponentExtras(Component& component, pugi::xml_node element)
{
    component.layout = guixml::readObjectLayout(element);
    component.preservedXml = serializeChildrenExcept(
        element, {"parameters", "startvalues", "simulationtime", "simulationlogsettings", "objects",
                  "connections", "aliases", "numhopscript"});
}

void storeSystemExtras(System& root, pugi::xml_node element)
{
    root.layout = guixml::readObjectLayout(element);
    root.liveControls = guixml::readLiveControls(element);
    root.preservedXml = serializeChildrenExcept(
        element, {"parameters", "simulationtime", "simulationlogsettings", "objects", "connections",
                  "aliases", "numhopscript"});
}

void storeDocumentExtras(System& root, pugi::xml_node top)
{
    root.preservedDocumentXml = serializeChildrenExcept(top, {"system"});
}

void storeSystemPortExtras(System& system, const std::string& portName, pugi::xml_node element)
{
    system.systemPortExtras[portName] = {guixml::readObjectLayout(element), serializeChildrenExcept(element, {})};
}

std::string connectionKey(const std::string& a, const std::string& pa, const std::string& b,
                          const std::string& pb)
{
    return a + "." + pa + "|" + b + "." + pb;
}

ConnectionKeyParts parseConnectionKey(const std::string& key)
{
    const std::size_t bar = key.find('|');
    const std::string a = key.substr(0, bar);
    const std::string b = bar == std::string::npos ? std::string() : key.substr(bar + 1);
    auto split = [](const std::string& end) -> std::pair<std::string, std::string> {
        const std::size_t dot = end.find('.');
        if (dot == std::string::npos) return {end, std::string()};
        return {end.substr(0, dot), end.substr(dot + 1)};
    };
    auto [ca, pa] = split(a);
    auto [cb, pb] = split(b);
    return {ca, pa, cb, pb};
}

void storeConnectionExtras(System& system, const std::string& a, const std::string& pa,
                           const std::string& b, const std::string& pb, pugi::xml_node element)
{
    system.connectionExtras[connectionKey(a, pa, b, pb)] = {guixml::readConnectionLayout(element),
                                                            serializeChildrenExcept(element, {})};
}

void storeOtherObject(System& system, pugi::xml_node element)
{
    std::ostringstream os;
    element.print(os, "", pugi::format_raw);
    system.preservedObjectsXml.push_back(os.str());
}

void appendFragment(pugi::xml_node parent, const std::string& xml)
{
    if (xml.empty()) return;
    pugi::xml_document frag;
    if (!frag.load_buffer(xml.data(), xml.size(), pugi::parse_default | pugi::parse_fragment)) return;
    for (pugi::xml_node child : frag.children()) parent.append_copy(child);
}

} // namespace tlmhub::preserved
