#pragma once
// Validation against Hopsan reference results: .hvc files and the pass rule of core.md §7.
#include <string>
#include <vector>

namespace tlmhub {

struct VariableCheck {
    std::string name;
    double tolerance = 0.01;
    bool passed = false;
    double worstDeviation = 0.0;   // largest |1 - sim/ref| among checked samples
    double worstTime = 0.0;        // time of that sample
    std::size_t failedSamples = 0;
    std::string error;             // set when the variable could not be checked at all
};

struct ValidationReport {
    std::string hvcPath;
    std::string modelPath;
    std::string error;             // model/file level failure
    std::vector<VariableCheck> variables;
    std::size_t passed() const;
    std::size_t failed() const;
    bool allPassed() const { return error.empty() && failed() == 0 && !variables.empty(); }
};

// The element-wise rule: sample i fails iff |1-sim/ref| > tol, |sim| >= 1e-100, |ref| >= 1e-10.
bool sampleFails(double sim, double ref, double tol);

// Linear interpolation of (t, v) at x with Hopsan's interval convention (core.md §7.3).
double interpolateReference(const std::vector<double>& t, const std::vector<double>& v, double x);

ValidationReport validateHvc(const std::string& hvcPath);

} // namespace tlmhub
