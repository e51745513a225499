#pragma once
// The automatic checks of an assignment: what a check asks (its definition, as the teacher
// writes it in JSON) and how a run is judged against it. A "curve" check compares a variable
// over time with the teacher's reference run (interpolated at the run's times), by default by
// the .hvc rule (core.md §7.4: a tolerance relative to each reference sample) or, with
// "scale": "range", relative to the reference's largest magnitude over the run (so a curve
// through zero is not failed by tiny differences there); a "scalar" check computes one measure
// of a variable of the run (final value, min, max, overshoot in %, settling time, rise time
// 10-90 %) and requires it within bounds.
#include "server/store/LabStore.h"

#include "core/ResultTable.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <span>
#include <string>
#include <vector>

namespace tlmhub::server {

struct CheckDefinition {
    std::string kind;                    // "curve" or "scalar"
    std::string variable;                // a result column name, e.g. "Mass#P1#x"
    std::string measure;                 // scalar: final, min, max, overshoot, settling_time, rise_time
    double tolerance = 0.01;             // curve: relative tolerance
    // curve: "" (not given: the .hvc rule, as before the field existed), "sample" (the same
    // rule, named) or "range" (|run - reference| <= tolerance * max |reference| over the run)
    std::string scale;
    std::optional<double> min, max;      // scalar: inclusive bounds (at least one)
    double band = 0.02;                  // settling_time: ± band around the final value, relative
};

// Reads and checks a definition ({"kind": ..., "variable": ..., ...}); nullopt with `error`
// naming the field that is wrong.
std::optional<CheckDefinition> parseCheckDefinition(const nlohmann::json& json, std::string& error);
nlohmann::json checkDefinitionJson(const CheckDefinition& definition);

struct CheckOutcome {
    std::string name;
    bool pretest = false;
    bool passed = false;
    double points = 0, awarded = 0;      // awarded = points when passed, else 0
    std::optional<double> value;         // scalar: the measure of the run
    // curve: largest |1 - run/reference| among compared samples, or with "scale": "range" the
    // largest |run - reference| / max |reference|
    std::optional<double> deviation;
    std::optional<double> worstTime;     // curve: the time of that sample
    std::string message;                 // why it failed ("" when passed)
};

// Judges `run` by each check (all, or only the pretests); `reference` is the teacher's
// reference run (needed by curve checks; a curve check without it fails with a message).
std::vector<CheckOutcome> evaluateChecks(const std::vector<AssignmentCheck>& checks, const ResultTable& run,
                                         const ResultTable* reference, bool pretestsOnly);
nlohmann::json outcomesJson(const std::vector<CheckOutcome>& outcomes);
// Outcomes (outcomesJson's form) as a student may see them: of a check hidden from students
// (not a pretest) only its name, pass or fail and points. Its bounds, deviation, worst time
// and message would give the reference away.
nlohmann::json outcomesForStudent(const nlohmann::json& outcomes);

// Step-response measures of a logged variable (times increasing). Settling time: the first
// time after which the variable stays within ±band·|final - initial| of its final value (0 when
// always within). Rise time: from the first reaching of 10 % to the first reaching of 90 % of
// the change from the first to the final value; nullopt when it does not change.
double settlingTime(std::span<const double> time, std::span<const double> values, double band);
std::optional<double> riseTime(std::span<const double> time, std::span<const double> values);

} // namespace tlmhub::server
