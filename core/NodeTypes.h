#pragma once
// Node types and the layout of their data vectors (core.md §1).
// The slot order is the storage order: components, logs and names all index by it.
#include <cstddef>
#include <string_view>
#include <vector>

namespace tlmhub {

enum class NodeType {
    Empty,               // type of an unconnected system port
    Hydraulic,
    HydraulicTemperature,
    Mechanic,
    MechanicRotational,
    Electric,
    Signal,
    Pneumatic,
    Mechanic2D,
    Signal2D,
    Signal3D,
    PetriNet,
};

enum class NodeVariableKind { Default, Intensity, Flow, TLM, Hidden };

struct NodeVariableInfo {
    std::string_view name;
    std::string_view shortName;
    std::string_view unit;
    NodeVariableKind kind;
    double createdValue;
};

struct NodeTypeInfo {
    NodeType type;
    std::string_view typeName;   // "NodeHydraulic"
    std::string_view niceName;   // "hydraulic"
    std::vector<NodeVariableInfo> variables;
    // TLM copy rule of start values: data[waveSlot] := data[intensitySlot] (pairs).
    std::vector<std::pair<int, int>> tlmCopyRule;
};

const NodeTypeInfo& nodeTypeInfo(NodeType type);
// Accepts both "NodeHydraulic" and "hydraulic"; returns false if unknown.
bool nodeTypeFromName(std::string_view name, NodeType& out);
// Index of a variable by long name, -1 if absent.
int nodeVariableIndex(NodeType type, std::string_view variableName);
inline std::size_t nodeSize(NodeType type) { return nodeTypeInfo(type).variables.size(); }

// Slot ids, named as Hopsan's component code names them.
namespace NodeHydraulic {
enum : int { Flow = 0, Pressure, Temperature, WaveVariable, CharImpedance, HeatFlow };
}
namespace NodeMechanic {
enum : int { Velocity = 0, Force, Position, WaveVariable, CharImpedance, EquivalentMass };
}
namespace NodeMechanicRotational {
enum : int { AngularVelocity = 0, Torque, Angle, WaveVariable, CharImpedance, EquivalentInertia };
}
namespace NodeElectric {
enum : int { Voltage = 0, Current, WaveVariable, CharImpedance };
}
namespace NodeSignal {
enum : int { Value = 0 };
}
namespace NodePneumatic {
enum : int {
    EnergyFlow = 0, Pressure, WaveVariable, CharImpedance, MassFlow, Density,
    DensityWaveVariable, DensityCharImpedance, Temperature
};
}
namespace NodePetriNet {
enum : int { State = 0, Flow };   // place marking, token transfer this step
}
namespace NodeMechanic2D {
enum : int {
    AngleR = 0, AngularVelocityR, TorqueR, WaveVariableR, CharImpedanceR, EquivalentInertiaR,
    PositionX, VelocityX, ForceX, WaveVariableX, CharImpedanceX, EquivalentMassX,
    PositionY, VelocityY, ForceY, WaveVariableY, CharImpedanceY, EquivalentMassY
};
}

} // namespace tlmhub
