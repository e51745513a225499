#pragma once
// GUI layout kept in a model's preserved XML (the <hopsangui> children the core stores but
// does not interpret): a component's or system port's pose, and a connection's line points.
// Reading never fails (missing data gives defaults); writing changes only the element it
// is about and keeps every other preserved child as it was, so Hopsan still reads the file.
#include <array>
#include <string>
#include <vector>

namespace tlmhub::server {

// Placement as in <hopsangui><pose x y a flipped/>; angle in degrees.
struct Pose {
    double x = 0.0;
    double y = 0.0;
    double angle = 0.0;
    bool flipped = false;
};

using LinePoint = std::array<double, 2>;

Pose readPose(const std::string& preservedXml);
void writePose(std::string& preservedXml, const Pose& pose);

// <hopsangui><coordinates><coordinate x y/>... of a connection.
std::vector<LinePoint> readLinePoints(const std::string& preservedXml);
// Replaces the coordinates (and the per-segment <geometries> Hopsan derives from them).
void writeLinePoints(std::string& preservedXml, const std::vector<LinePoint>& points);

} // namespace tlmhub::server
