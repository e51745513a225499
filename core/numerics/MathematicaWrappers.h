// Thin wrappers so that equations exported from Mathematica compile verbatim
// (utilities.md §3). No regularisation is added.
#pragma once

#include <cmath>

namespace tlmhub {

inline double Power(double x, double y) { return std::pow(x, y); }
inline double Sin(double x) { return std::sin(x); }
inline double Cos(double x) { return std::cos(x); }
inline double Tan(double x) { return std::tan(x); }
inline double Cot(double x) { return 1.0 / std::tan(x); }
inline double Csc(double x) { return 1.0 / std::sin(x); }
inline double Sec(double x) { return 1.0 / std::cos(x); }
inline double SecL(double x) { return 1.0 / std::cos(x); }
inline double DxSecL(double x) { return std::tan(x) / std::cos(x); }
inline double Sqrt(double x) { return std::sqrt(x); }
inline double Abs(double x) { return std::fabs(x); }

} // namespace tlmhub
