#pragma once
// A model's GUI layout as typed values: where each component, system port and connection
// line is drawn. The loader reads them from a model file's <hopsangui> elements, the saver
// writes them back (core/hmf/GuiLayoutXml.h); everything else of <hopsangui> stays
// preserved XML (Component::preservedXml).
//
// Why typed values beside the preserved XML, and not the XML kept in sync on every change:
// the values are plain fields (anyone may assign them), so nothing could re-serialize the
// XML at each assignment. Instead the saver compares each value with what the preserved XML
// says and rewrites only what differs. An unchanged model saves byte for byte as before; a
// changed value rewrites only its own attributes or element, and every other child of
// <hopsangui> stays where it was, so Hopsan still reads the file.
#include <array>
#include <optional>
#include <string>
#include <vector>

namespace tlmhub {

// Placement as in <hopsangui><pose x y a flipped/>: scene coordinates, angle in degrees.
// A file without <pose> places the object as Hopsan does: at the origin, not rotated.
struct Pose {
    double x = 0.0;
    double y = 0.0;
    double angle = 0.0;
    bool flipped = false;
    bool operator==(const Pose&) const = default;
};

// The name label, <hopsangui><nametext position visible/>: Hopsan's position code (which
// side of the icon) and whether it is shown.
struct NameText {
    int position = 0;
    bool visible = false;
    bool operator==(const NameText&) const = default;
};

// A port's place on the object's icon,
// <hopsangui><hopsanobjectappearance><modelobject><ports><port name x y a autoplaced enabled/>:
// x and y are fractions of the icon's width and height, the angle in degrees.
struct IconPort {
    std::string name;
    double x = 0.0;
    double y = 0.0;
    double angle = 0.0;
    bool autoplaced = true;
    bool enabled = true;
    bool operator==(const IconPort&) const = default;
};

// The layout of a component, subsystem or system port.
struct ObjectLayout {
    Pose pose;
    // None when the file has no <nametext> (Hopsan then uses its own default).
    std::optional<NameText> nameText;
    // Ports placed on the icon, as the file lists them (Hopsan writes them for subsystems,
    // whose icons show their system ports); empty when the file places none.
    std::vector<IconPort> iconPorts;
    bool operator==(const ObjectLayout&) const = default;
};

// A control the web app places on the top-level drawing or a subsystem's, to change one value
// while the model runs (docs/live-mode.md), kept in the root system's
// <hopsangui><tlmhub_livecontrols><control kind name min max x y [system off on]/>. Hopsan
// does not read the element.
struct LiveControlLayout {
    std::string kind;                  // slider, knob, switch or number
    std::string name;                  // the value it sets, as live.set names it: Step.y_A, Sub$Gain.k
    double min = 0.0, max = 1.0;
    std::optional<double> off, on;     // a switch's two values
    double x = 0.0, y = 0.0;           // in the coordinates of the drawing it is on
    std::vector<std::string> system;   // that drawing's subsystem path; empty: the top level
    bool operator==(const LiveControlLayout&) const = default;
};

// A point of a connection's line, {x, y} in scene coordinates.
using LinePoint = std::array<double, 2>;

// The line of a connection, <hopsangui><coordinates><coordinate x y/>..., from the start
// end to the end end as the model lists the connection. Empty: no line stored.
struct ConnectionLayout {
    std::vector<LinePoint> points;
    bool operator==(const ConnectionLayout&) const = default;
};

} // namespace tlmhub
