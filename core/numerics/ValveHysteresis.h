// Backlash-type hysteresis (utilities.md §12). Stateless: the caller passes
// the previous output xd.
#pragma once

namespace tlmhub {

class ValveHysteresis
{
public:
    // xs: input, xh: total hysteresis width, xd: previous (delayed) output.
    double getValue(double xs, double xh, double xd) const
    {
        const double lo = xs - xh / 2.0;
        const double hi = xs + xh / 2.0;
        if (xd < lo) { return lo; }
        if (xd > hi) { return hi; }
        return xd;
    }
};

} // namespace tlmhub
