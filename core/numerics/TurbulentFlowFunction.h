// Closed-form turbulent orifice flow between two TLM ports (utilities.md §11).
// Solves q = Ks*sign(p1-p2)*sqrt(|p1-p2|) with p1 = c1 + Zc1*q1, p2 = c2 + Zc2*q2,
// q2 = -q1 = q. Returned q is positive from port 1 to port 2.
#pragma once

#include <cmath>

namespace tlmhub {

class TurbulentFlowFunction
{
public:
    TurbulentFlowFunction() = default;
    explicit TurbulentFlowFunction(double Ks) : mKs(Ks) {}

    void setFlowCoefficient(double Ks) { mKs = Ks; }
    double flowCoefficient() const { return mKs; }

    double getFlow(double c1, double c2, double Zc1, double Zc2) const
    {
        const double Ks = mKs;
        if (c1 > c2) {
            return Ks * (std::sqrt(c1 - c2 + (Zc1 + Zc2) * (Zc1 + Zc2) * Ks * Ks / 4.0) - Ks * (Zc1 + Zc2) / 2.0);
        }
        return Ks * (Ks * (Zc1 + Zc2) / 2.0 - std::sqrt(c2 - c1 + (Zc1 + Zc2) * (Zc1 + Zc2) * Ks * Ks / 4.0));
    }

private:
    double mKs = 0.0; // the reference has no default; 0 avoids reading garbage
};

} // namespace tlmhub
