#pragma once
// Every parameter value string of a model by its path (core/ParameterPath.h syntax: "param",
// "Comp.param", "Sub.param", "Sub$Comp.param"; start values as "Comp.P#Value"): what a run
// used, to be compared with another version of the model.
#include <map>
#include <string>

namespace tlmhub {

class System;

std::map<std::string, std::string> parameterTexts(const System& root);

} // namespace tlmhub
