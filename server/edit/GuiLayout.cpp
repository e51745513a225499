#include "server/edit/GuiLayout.h"

#include "core/Parameter.h"

#include <pugixml.hpp>

#include <cmath>
#include <sstream>

namespace tlmhub::server {

namespace {

bool parseFragment(pugi::xml_document& doc, const std::string& xml)
{
    if (xml.empty()) return true;
    return doc.load_buffer(xml.data(), xml.size(), pugi::parse_default | pugi::parse_fragment);
}

std::string serializeFragment(const pugi::xml_document& doc)
{
    std::ostringstream os;
    for (pugi::xml_node child : doc.children()) child.print(os, "", pugi::format_raw);
    return os.str();
}

pugi::xml_node childOrNew(pugi::xml_node parent, const char* name, bool first = false)
{
    pugi::xml_node child = parent.child(name);
    if (child) return child;
    return first ? parent.prepend_child(name) : parent.append_child(name);
}

// Numbers written as the model file writes parameters: shortest round-trip form.
void setNumber(pugi::xml_node node, const char* attribute, double value)
{
    pugi::xml_attribute a = node.attribute(attribute);
    if (!a) a = node.append_attribute(attribute);
    a.set_value(formatNumber(value).c_str());
}

double finiteOr(double value, double fallback) { return std::isfinite(value) ? value : fallback; }

// Edits the fragment in `xml` with `edit`; a fragment that does not parse is kept and the
// edit goes into a fresh <hopsangui> appended after it.
template <typename Edit>
void editFragment(std::string& xml, Edit edit)
{
    pugi::xml_document doc;
    if (parseFragment(doc, xml)) {
        edit(doc);
        xml = serializeFragment(doc);
        return;
    }
    pugi::xml_document fresh;
    edit(fresh);
    xml += serializeFragment(fresh);
}

} // namespace

Pose readPose(const std::string& preservedXml)
{
    Pose pose;
    pugi::xml_document doc;
    if (!parseFragment(doc, preservedXml)) return pose;
    pugi::xml_node p = doc.child("hopsangui").child("pose");
    pose.x = finiteOr(p.attribute("x").as_double(0.0), 0.0);
    pose.y = finiteOr(p.attribute("y").as_double(0.0), 0.0);
    pose.angle = finiteOr(p.attribute("a").as_double(0.0), 0.0);
    pose.flipped = p.attribute("flipped").as_bool(false);
    return pose;
}

void writePose(std::string& preservedXml, const Pose& pose)
{
    editFragment(preservedXml, [&pose](pugi::xml_document& doc) {
        pugi::xml_node gui = childOrNew(doc, "hopsangui");
        pugi::xml_node p = childOrNew(gui, "pose", true);
        setNumber(p, "x", pose.x);
        setNumber(p, "y", pose.y);
        setNumber(p, "a", pose.angle);
        pugi::xml_attribute flipped = p.attribute("flipped");
        if (!flipped) flipped = p.append_attribute("flipped");
        flipped.set_value(pose.flipped ? "true" : "false");
    });
}

std::vector<LinePoint> readLinePoints(const std::string& preservedXml)
{
    std::vector<LinePoint> points;
    pugi::xml_document doc;
    if (!parseFragment(doc, preservedXml)) return points;
    for (pugi::xml_node c : doc.child("hopsangui").child("coordinates").children("coordinate"))
        points.push_back({finiteOr(c.attribute("x").as_double(0.0), 0.0),
                          finiteOr(c.attribute("y").as_double(0.0), 0.0)});
    return points;
}

void writeLinePoints(std::string& preservedXml, const std::vector<LinePoint>& points)
{
    editFragment(preservedXml, [&points](pugi::xml_document& doc) {
        pugi::xml_node gui = childOrNew(doc, "hopsangui");
        gui.remove_child("coordinates");
        gui.remove_child("geometries");
        pugi::xml_node coordinates = gui.prepend_child("coordinates");
        for (const LinePoint& p : points) {
            pugi::xml_node c = coordinates.append_child("coordinate");
            setNumber(c, "x", p[0]);
            setNumber(c, "y", p[1]);
        }
        // Hopsan names each segment by the direction it can be dragged: a horizontal
        // segment moves vertically and the other way round.
        pugi::xml_node geometries = coordinates.parent().insert_child_after("geometries", coordinates);
        for (std::size_t i = 1; i < points.size(); ++i) {
            const bool sameY = points[i][1] == points[i - 1][1];
            const bool sameX = points[i][0] == points[i - 1][0];
            const char* g = sameY ? "vertical" : (sameX ? "horizontal" : "diagonal");
            geometries.append_child("geometry").text().set(g);
        }
    });
}

} // namespace tlmhub::server
