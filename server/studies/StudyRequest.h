#pragma once
// What a study asks for (POST /api/v1/studies, docs/studies.md): the model, the settings and
// fixed parameters of every run, the outputs kept per run, and the kind's own part (a sweep's
// axes, a sensitivity study's distributions, an optimisation's bounds and objective).
#include "server/jobs/Job.h"
#include "server/studies/Optimiser.h"
#include "server/studies/ParameterSampling.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace tlmhub::server {

enum class StudyKind { Sweep, Sensitivity, Optimise };
const char* studyKindName(StudyKind kind);

// A scalar of one variable over a run.
enum class RunStatistic { Final, Min, Max, Mean };
const char* runStatisticName(RunStatistic statistic);

struct StudyOutputs {
    std::vector<std::string> variables;     // result names, "Comp#Port#Var"
    std::vector<RunStatistic> statistics;   // each variable × each statistic is a column
    bool full = false;                      // keep every run's whole result
    // "Var:final", ... in column order.
    std::vector<std::string> columnNames() const;
};

struct ObjectiveTerm {
    enum class Function { Final, Min, Max, Mean, Overshoot, Ise } function = Function::Final;
    std::string variable;
    std::string referenceVariable;                        // ise against another variable
    std::vector<std::pair<double, double>> referenceCurve;  // ise against (time, value) points
    std::optional<double> target;                         // final/min/max/mean: squared distance
    double weight = 1.0;
};

struct StudyObjective {
    bool maximise = false;
    std::vector<ObjectiveTerm> terms;
};

struct StudyRequest {
    StudyKind kind = StudyKind::Sweep;
    std::string name;
    std::optional<std::int64_t> modelId;
    std::string hmf;   // the model's text (from model_id, or given)
    JobSettings settings;
    std::map<std::string, std::string> fixedParameters;
    StudyOutputs outputs;

    // sweep
    std::vector<SweepAxis> axes;
    SweepMode mode = SweepMode::Grid;
    std::size_t samples = 0;
    std::uint64_t seed = 1;
    // sensitivity (also uses seed)
    std::vector<RandomParameter> distributions;
    std::size_t runs = 0;
    // optimise
    OptimiserSettings optimiser;
    // An optimisation's objective; a sweep or sensitivity study may have one too (its table
    // then has the column "objective", e.g. to compare a sweep with an optimisation).
    std::optional<StudyObjective> objective;
    // The study ends failed once at least kMinRunsForFailedFraction runs have finished and
    // more than this fraction of them failed; 1 (the default) never stops it.
    double maxFailedFraction = 1.0;
    static constexpr std::int64_t kMinRunsForFailedFraction = 10;

    // The varied parameters' names, in the order of a run's values.
    std::vector<std::string> parameterNames() const;
    // Runs planned: a sweep's sets, a sensitivity study's runs, an optimisation's budget.
    std::size_t plannedRuns() const;
};

// Reads and checks a request body (the model's text is not needed yet: `hmf` or `model_id`
// must be there). False with a message naming what is wrong.
bool parseStudyRequest(const nlohmann::json& body, StudyRequest& out, std::string& error);

} // namespace tlmhub::server
