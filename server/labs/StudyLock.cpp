#include "server/labs/StudyLock.h"

#include "server/studies/ParameterSampling.h"

namespace tlmhub::server {

namespace {

std::string rangeProblem(const ParameterLock& lock, const std::string& name, double low, double high)
{
    if (std::string problem = lock.numberProblem(name, low); !problem.empty()) return problem;
    return lock.numberProblem(name, high);
}

} // namespace

std::string studyLockProblem(const StudyRequest& request, const ParameterLock& lock)
{
    for (const auto& [name, value] : request.fixedParameters)
        if (std::string problem = lock.valueProblem(name, value); !problem.empty()) return problem;
    for (const SweepAxis& axis : request.axes)
        for (const double value : axisValues(axis))
            if (std::string problem = lock.numberProblem(axis.name, value); !problem.empty()) return problem;
    for (const RandomParameter& p : request.distributions) {
        if (p.distribution.kind == Distribution::Kind::Uniform) {
            if (std::string problem = rangeProblem(lock, p.name, p.distribution.a, p.distribution.b); !problem.empty())
                return problem;
            continue;
        }
        // A normal distribution has no bounds: only an unbounded parameter takes it.
        const std::string problem = lock.valueProblem(p.name, "not a number");
        if (!problem.empty()) return problem + " (a normal distribution can leave any bounds)";
    }
    for (const ParameterBounds& p : request.optimiser.parameters)
        if (std::string problem = rangeProblem(lock, p.name, p.min, p.max); !problem.empty()) return problem;
    return "";
}

} // namespace tlmhub::server
