#pragma once
// The control-surface ports the 6-DOF aircraft components share (rotational nodes: the
// surfaces' deflection angles in, their hinge moments out), in port order.
namespace tlmhub::aircraft {

inline constexpr const char* kControlSurfacePortNames[7] = {"Pal1", "Par1", "Pal12", "Par12",
                                                            "Pal2", "Par2", "Pfin"};
enum ControlSurface { al1 = 0, ar1, al12, ar12, al2, ar2, fin };

} // namespace tlmhub::aircraft
