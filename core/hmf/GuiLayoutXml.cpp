#include "core/hmf/GuiLayoutXml.h"

#include "core/Parameter.h"

#include <algorithm>
#include <cmath>

namespace tlmhub::guixml {

namespace {

double readNumber(pugi::xml_attribute a)
{
    const double value = a.as_double(0.0);
    return std::isfinite(value) ? value : 0.0;
}

pugi::xml_attribute attributeOrNew(pugi::xml_node node, const char* name)
{
    pugi::xml_attribute a = node.attribute(name);
    return a ? a : node.append_attribute(name);
}

// Numbers written as the model file writes parameters: the shortest round-trip form.
void setNumber(pugi::xml_node node, const char* name, double value)
{
    attributeOrNew(node, name).set_value(formatNumber(value).c_str());
}

// An attribute that already reads as the value keeps its text (and a missing one that reads
// as the default stays missing).
void updateNumber(pugi::xml_node node, const char* name, double value)
{
    if (readNumber(node.attribute(name)) != value) setNumber(node, name, value);
}

void updateBool(pugi::xml_node node, const char* name, bool value, bool fallback, const char* yes, const char* no)
{
    if (node.attribute(name).as_bool(fallback) != value) attributeOrNew(node, name).set_value(value ? yes : no);
}

pugi::xml_node childOrNew(pugi::xml_node parent, const char* name, bool& created)
{
    pugi::xml_node child = parent.child(name);
    created = !child;
    return child ? child : parent.append_child(name);
}

pugi::xml_node childOrNew(pugi::xml_node parent, const char* name)
{
    bool created = false;
    return childOrNew(parent, name, created);
}

Pose readPose(pugi::xml_node p)
{
    return {.x = readNumber(p.attribute("x")),
            .y = readNumber(p.attribute("y")),
            .angle = readNumber(p.attribute("a")),
            .flipped = p.attribute("flipped").as_bool(false)};
}

void writePose(pugi::xml_node gui, const Pose& pose)
{
    pugi::xml_node p = gui.child("pose");
    if (!p) {
        // A new <pose> is complete and first, as Hopsan writes it.
        p = gui.prepend_child("pose");
        setNumber(p, "x", pose.x);
        setNumber(p, "y", pose.y);
        setNumber(p, "a", pose.angle);
        p.append_attribute("flipped") = pose.flipped ? "true" : "false";
        return;
    }
    updateNumber(p, "x", pose.x);
    updateNumber(p, "y", pose.y);
    updateNumber(p, "a", pose.angle);
    updateBool(p, "flipped", pose.flipped, false, "true", "false");
}

NameText readNameText(pugi::xml_node n)
{
    return {.position = n.attribute("position").as_int(0), .visible = n.attribute("visible").as_bool(false)};
}

void writeNameText(pugi::xml_node gui, const std::optional<NameText>& nameText)
{
    if (!nameText) {
        gui.remove_child("nametext");
        return;
    }
    pugi::xml_node n = gui.child("nametext");
    if (!n) {
        // After the pose, as Hopsan writes it.
        pugi::xml_node pose = gui.child("pose");
        n = pose ? gui.insert_child_after("nametext", pose) : gui.append_child("nametext");
        n.append_attribute("position") = nameText->position;
        n.append_attribute("visible") = nameText->visible ? "1" : "0";
        return;
    }
    if (n.attribute("position").as_int(0) != nameText->position) attributeOrNew(n, "position") = nameText->position;
    updateBool(n, "visible", nameText->visible, false, "1", "0");
}

pugi::xml_node iconPortsElement(pugi::xml_node gui)
{
    return gui.child("hopsanobjectappearance").child("modelobject").child("ports");
}

IconPort readIconPort(pugi::xml_node p)
{
    return {.name = p.attribute("name").as_string(),
            .x = readNumber(p.attribute("x")),
            .y = readNumber(p.attribute("y")),
            .angle = readNumber(p.attribute("a")),
            .autoplaced = p.attribute("autoplaced").as_bool(true),
            .enabled = p.attribute("enabled").as_bool(true)};
}

void updateIconPort(pugi::xml_node p, const IconPort& port)
{
    if (std::string(p.attribute("name").as_string()) != port.name) attributeOrNew(p, "name") = port.name.c_str();
    updateNumber(p, "x", port.x);
    updateNumber(p, "y", port.y);
    updateNumber(p, "a", port.angle);
    updateBool(p, "autoplaced", port.autoplaced, true, "true", "false");
    updateBool(p, "enabled", port.enabled, true, "true", "false");
}

// A new <ports> list in place of the old one: a port the old list names keeps its element
// (and any attributes not typed here), a new port gets a complete element.
void writeIconPorts(pugi::xml_node gui, const std::vector<IconPort>& ports)
{
    bool createdAppearance = false;
    pugi::xml_node appearance = childOrNew(gui, "hopsanobjectappearance", createdAppearance);
    if (createdAppearance) appearance.append_attribute("version") = "0.3";
    pugi::xml_node modelObject = childOrNew(appearance, "modelobject");
    pugi::xml_node old = modelObject.child("ports");
    pugi::xml_node list = old ? modelObject.insert_child_before("ports", old) : modelObject.append_child("ports");
    for (const IconPort& port : ports) {
        const pugi::xml_node kept = old.find_child_by_attribute("port", "name", port.name.c_str());
        if (kept) {
            updateIconPort(list.append_copy(kept), port);
            continue;
        }
        pugi::xml_node p = list.append_child("port");
        p.append_attribute("name") = port.name.c_str();
        setNumber(p, "x", port.x);
        setNumber(p, "y", port.y);
        setNumber(p, "a", port.angle);
        p.append_attribute("autoplaced") = port.autoplaced ? "true" : "false";
        p.append_attribute("enabled") = port.enabled ? "true" : "false";
    }
    if (old) modelObject.remove_child(old);
}

constexpr const char* kLiveControls = "tlmhub_livecontrols";

std::optional<double> readOptionalNumber(pugi::xml_attribute a)
{
    return a ? std::optional(readNumber(a)) : std::nullopt;
}

std::vector<std::string> splitSystemPath(const std::string& text)
{
    std::vector<std::string> path;
    for (std::size_t from = 0; from < text.size();) {
        const std::size_t to = std::min(text.find('$', from), text.size());
        if (to > from) path.push_back(text.substr(from, to - from));
        from = to + 1;
    }
    return path;
}

std::string joinSystemPath(const std::vector<std::string>& path)
{
    std::string text;
    for (const std::string& name : path) {
        if (!text.empty()) text += '$';
        text += name;
    }
    return text;
}

} // namespace

std::vector<LiveControlLayout> readLiveControls(pugi::xml_node element)
{
    std::vector<LiveControlLayout> controls;
    for (pugi::xml_node c : element.child("hopsangui").child(kLiveControls).children("control")) {
        controls.push_back({.kind = c.attribute("kind").as_string(),
                            .name = c.attribute("name").as_string(),
                            .min = readNumber(c.attribute("min")),
                            .max = readNumber(c.attribute("max")),
                            .off = readOptionalNumber(c.attribute("off")),
                            .on = readOptionalNumber(c.attribute("on")),
                            .x = readNumber(c.attribute("x")),
                            .y = readNumber(c.attribute("y")),
                            .system = splitSystemPath(c.attribute("system").as_string())});
    }
    return controls;
}

void writeLiveControls(pugi::xml_node element, const std::vector<LiveControlLayout>& controls)
{
    if (readLiveControls(element) == controls) return;
    pugi::xml_node gui = childOrNew(element, "hopsangui");
    gui.remove_child(kLiveControls);
    if (controls.empty()) return;
    pugi::xml_node list = gui.append_child(kLiveControls);
    for (const LiveControlLayout& control : controls) {
        pugi::xml_node c = list.append_child("control");
        c.append_attribute("kind") = control.kind.c_str();
        c.append_attribute("name") = control.name.c_str();
        setNumber(c, "min", control.min);
        setNumber(c, "max", control.max);
        if (control.off) setNumber(c, "off", *control.off);
        if (control.on) setNumber(c, "on", *control.on);
        setNumber(c, "x", control.x);
        setNumber(c, "y", control.y);
        if (!control.system.empty()) c.append_attribute("system") = joinSystemPath(control.system).c_str();
    }
}

ObjectLayout readObjectLayout(pugi::xml_node element)
{
    const pugi::xml_node gui = element.child("hopsangui");
    ObjectLayout layout;
    layout.pose = readPose(gui.child("pose"));
    if (pugi::xml_node n = gui.child("nametext")) layout.nameText = readNameText(n);
    for (pugi::xml_node p : iconPortsElement(gui).children("port")) layout.iconPorts.push_back(readIconPort(p));
    return layout;
}

void writeObjectLayout(pugi::xml_node element, const ObjectLayout& layout)
{
    const ObjectLayout stored = readObjectLayout(element);
    if (stored == layout) return;
    pugi::xml_node gui = childOrNew(element, "hopsangui");
    if (stored.pose != layout.pose) writePose(gui, layout.pose);
    if (stored.nameText != layout.nameText) writeNameText(gui, layout.nameText);
    if (stored.iconPorts != layout.iconPorts) writeIconPorts(gui, layout.iconPorts);
}

ConnectionLayout readConnectionLayout(pugi::xml_node connect)
{
    ConnectionLayout layout;
    for (pugi::xml_node c : connect.child("hopsangui").child("coordinates").children("coordinate"))
        layout.points.push_back({readNumber(c.attribute("x")), readNumber(c.attribute("y"))});
    return layout;
}

void writeConnectionLayout(pugi::xml_node connect, const ConnectionLayout& layout)
{
    if (readConnectionLayout(connect) == layout) return;
    pugi::xml_node gui = childOrNew(connect, "hopsangui");
    gui.remove_child("coordinates");
    gui.remove_child("geometries");
    if (layout.points.empty()) return;
    pugi::xml_node coordinates = gui.prepend_child("coordinates");
    for (const LinePoint& p : layout.points) {
        pugi::xml_node c = coordinates.append_child("coordinate");
        setNumber(c, "x", p[0]);
        setNumber(c, "y", p[1]);
    }
    // Hopsan names each segment by the direction it can be dragged: a horizontal segment
    // moves vertically and the other way round.
    pugi::xml_node geometries = gui.insert_child_after("geometries", coordinates);
    for (std::size_t i = 1; i < layout.points.size(); ++i) {
        const bool sameY = layout.points[i][1] == layout.points[i - 1][1];
        const bool sameX = layout.points[i][0] == layout.points[i - 1][0];
        geometries.append_child("geometry").text().set(sameY ? "vertical" : (sameX ? "horizontal" : "diagonal"));
    }
}

} // namespace tlmhub::guixml
