#include "core/NodeTypes.h"

#include <array>

namespace tlmhub {
namespace {

using K = NodeVariableKind;

std::vector<NodeTypeInfo> buildTable()
{
    std::vector<NodeTypeInfo> t;
    t.push_back({NodeType::Empty, "NodeEmpty", "empty", {}, {}});
    std::vector<NodeVariableInfo> hyd = {
        {"Flow", "q", "m^3/s", K::Flow, 0.0},
        {"Pressure", "p", "Pa", K::Intensity, 1e5},
        {"Temperature", "T", "K", K::Hidden, 293.0},
        {"WaveVariable", "c", "Pa", K::TLM, 1e5},
        {"CharImpedance", "Zc", "Pa s/m^3", K::TLM, 0.0},
        {"HeatFlow", "Qdot", "?", K::Hidden, 0.0},
    };
    t.push_back({NodeType::Hydraulic, "NodeHydraulic", "hydraulic", hyd, {{3, 1}}});
    t.push_back({NodeType::HydraulicTemperature, "NodeHydraulicTemperature", "hydraulictemperature",
                 hyd, {{3, 1}}});
    t.push_back({NodeType::Mechanic, "NodeMechanic", "mechanic",
                 {
                     {"Velocity", "v", "m/s", K::Flow, 0.0},
                     {"Force", "f", "N", K::Intensity, 0.0},
                     {"Position", "x", "m", K::Default, 0.0},
                     {"WaveVariable", "c", "N", K::TLM, 0.0},
                     {"CharImpedance", "Zc", "N s/m", K::TLM, 0.0},
                     {"EquivalentMass", "me", "kg", K::Default, 1.0},
                 },
                 {{3, 1}}});
    t.push_back({NodeType::MechanicRotational, "NodeMechanicRotational", "mechanicrotational",
                 {
                     {"AngularVelocity", "w", "rad/s", K::Flow, 0.0},
                     {"Torque", "T", "Nm", K::Intensity, 0.0},
                     {"Angle", "a", "rad", K::Default, 0.0},
                     {"WaveVariable", "c", "Nm", K::TLM, 0.0},
                     {"CharImpedance", "Zc", "?", K::TLM, 0.0},
                     {"EquivalentInertia", "Je", "kg m^2", K::Hidden, 0.0},
                 },
                 {{3, 1}}});
    t.push_back({NodeType::Electric, "NodeElectric", "electric",
                 {
                     {"Voltage", "U", "V", K::Intensity, 0.0},
                     {"Current", "I", "A", K::Flow, 0.0},
                     {"WaveVariable", "c", "V", K::TLM, 0.0},
                     {"CharImpedance", "Zc", "V/A", K::TLM, 0.0},
                 },
                 {{2, 0}}});
    t.push_back({NodeType::Signal, "NodeSignal", "signal", {{"Value", "y", "", K::Default, 0.0}}, {}});
    t.push_back({NodeType::Pneumatic, "NodePneumatic", "pneumatic",
                 {
                     {"EnergyFlow", "Qdot", "J/s", K::Flow, 0.0},
                     {"Pressure", "p", "Pa", K::Intensity, 1e5},
                     {"WaveVariable", "c", "Pa", K::TLM, 1e5},
                     {"CharImpedance", "Zc", "s/m^3", K::TLM, 0.0},
                     {"MassFlow", "mdot", "kg/s", K::Flow, 0.0},
                     {"Density", "rho", "kg/m^3", K::Intensity, 1.225},
                     {"DensityWaveVariable", "crho", "kg/m^3", K::TLM, 1.225},
                     {"DensityCharImpedance", "Zcrho", "s/m^3", K::TLM, 0.0},
                     {"Temperature", "T", "K", K::Default, 293.0},
                 },
                 {{2, 1}}});
    t.push_back({NodeType::Mechanic2D, "NodeMechanic2D", "mechanic2d",
                 {
                     {"AngleR", "aR", "rad", K::Default, 0.0},
                     {"AngularVelocity", "wR", "rad/s", K::Flow, 0.0},
                     {"TorqueR", "TR", "Nm", K::Intensity, 0.0},
                     {"WaveVariableR", "cR", "Nm", K::TLM, 0.0},
                     {"CharImpedanceR", "ZcR", "?", K::TLM, 0.0},
                     {"EquivalentInertiaR", "JeR", "kg m^2", K::Default, 1.0},
                     {"PositionX", "xX", "m", K::Default, 0.0},
                     {"VelocityX", "vX", "m/s", K::Flow, 0.0},
                     {"ForceX", "fX", "N", K::Intensity, 0.0},
                     {"WaveVariableX", "cX", "N", K::TLM, 0.0},
                     {"CharImpedanceX", "ZcX", "N s/m", K::TLM, 0.0},
                     {"EquivalentMassX", "meX", "kg", K::Default, 1.0},
                     {"PositionY", "xY", "m", K::Default, 0.0},
                     {"VelocityY", "vY", "m/s", K::Flow, 0.0},
                     {"ForceY", "fY", "N", K::Intensity, 0.0},
                     {"WaveVariableY", "cY", "N", K::TLM, 0.0},
                     {"CharImpedanceY", "ZcY", "N s/m", K::TLM, 0.0},
                     {"EquivalentMassY", "meY", "kg", K::Default, 1.0},
                 },
                 {{3, 2}, {9, 8}, {15, 14}}});
    t.push_back({NodeType::Signal2D, "NodeSignal2D", "signal2d",
                 {{"v0", "y0", "", K::Default, 0.0}, {"v1", "y1", "", K::Default, 0.0}}, {}});
    t.push_back({NodeType::Signal3D, "NodeSignal3D", "signal3d",
                 {{"v0", "y0", "", K::Default, 0.0},
                  {"v1", "y1", "", K::Default, 0.0},
                  {"v2", "y2", "", K::Default, 0.0}},
                 {}});
    t.push_back({NodeType::PetriNet, "NodePetriNet", "petrinet",
                 {{"State", "s", "", K::Intensity, 0.0}, {"Flow", "q", "", K::Flow, 0.0}}, {}});
    return t;
}

const std::vector<NodeTypeInfo>& table()
{
    static const std::vector<NodeTypeInfo> t = buildTable();
    return t;
}

} // namespace

const NodeTypeInfo& nodeTypeInfo(NodeType type)
{
    return table()[static_cast<std::size_t>(type)];
}

bool nodeTypeFromName(std::string_view name, NodeType& out)
{
    for (const auto& info : table()) {
        if (info.typeName == name || info.niceName == name) {
            out = info.type;
            return true;
        }
    }
    return false;
}

int nodeVariableIndex(NodeType type, std::string_view variableName)
{
    const auto& vars = nodeTypeInfo(type).variables;
    for (std::size_t i = 0; i < vars.size(); ++i)
        if (vars[i].name == variableName) return static_cast<int>(i);
    return -1;
}

} // namespace tlmhub
