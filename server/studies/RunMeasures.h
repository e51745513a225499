#pragma once
// What a study keeps of one run: scalar measures of its variables (final value, min, max,
// time average, overshoot, integral of squared error) and the objective built from them.
#include "server/studies/StudyRequest.h"

#include "core/ResultView.h"

#include <optional>
#include <span>
#include <string>
#include <vector>

namespace tlmhub::server {

double finalValue(std::span<const double> values);
double minValue(std::span<const double> values);
double maxValue(std::span<const double> values);
// The time average (trapezoidal rule over the logged times); the value itself for one sample.
double timeAverage(std::span<const double> time, std::span<const double> values);
// Per cent by which the variable passes its final value, relative to its change from the first
// sample to the final one (a step response's overshoot); 0 when it does not pass it or does
// not change.
double overshootPercent(std::span<const double> values);
// ∫ (values - reference)² dt by the trapezoidal rule, the reference sampled at the same times.
double integralSquaredError(std::span<const double> time, std::span<const double> values,
                            std::span<const double> reference);
// The reference curve (increasing times) at time t: linear between points, constant beyond.
double interpolate(const std::vector<std::pair<double, double>>& curve, double t);

// The study's output columns (StudyOutputs::columnNames order) of a finished run; nullopt with
// `error` naming the variable when a variable is not in the result.
std::optional<std::vector<double>> runOutputs(const StudyOutputs& outputs, const ResultView& results,
                                              std::string& error);
// The objective of a finished run: the weighted sum of its terms (what the table shows; the
// optimiser minimises its negative for maximise).
std::optional<double> runObjective(const StudyObjective& objective, const ResultView& results, std::string& error);
// The names of result variables the study reads; what submit checks against the model.
std::vector<std::string> variablesRead(const StudyRequest& request);

} // namespace tlmhub::server
