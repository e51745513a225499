#pragma once
// The JSON bodies the remote commands send, built from their options as docs/studies.md
// describes: job parameters (--param), and the POST /studies request of `remote sweep`
// (--vary, --mode, --output, --full) and `remote optimise` (--bound, --objective, ...).
// Option text that does not fit is a UsageError.
#include "cli/remote/Arguments.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace tlmhub::cli::remote {

// "Comp.P=value"... -> {"Comp.P": value}: a number when the text is one, else the text (an
// expression or a system parameter's name, which the server evaluates).
nlohmann::json parameterValues(const std::vector<std::string>& assignments);

// The study requests leave out "model_id": the caller adds it once the options have been
// checked and the model is uploaded.

// Both take --param Comp.P=value (fixed for every run) and --start/--step/--stop.
// --vary "Comp.P=1:5:10" -> {"from": 1, "to": 5, "steps": 10}; "Comp.P=1,2,3" -> [1, 2, 3];
// --mode random --samples N [--seed S] samples --vary "Comp.P=from:to".
nlohmann::json sweepRequest(const std::string& name, const Arguments& args);

// --distribution "Comp.P=normal:MEAN:SD" or "Comp.P=uniform:MIN:MAX", --runs N, --seed S,
// --output as a sweep's (at least one).
nlohmann::json sensitivityRequest(const std::string& name, const Arguments& args);

// --bound "Comp.P=min:max", --objective "FUNCTION:VARIABLE[:REFERENCE_VARIABLE][*WEIGHT]",
// --algorithm, --maximise, --max-evaluations, --seed, --tolerance.
nlohmann::json optimiseRequest(const std::string& name, const Arguments& args);

} // namespace tlmhub::cli::remote
