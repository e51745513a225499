#include "fmu/ModelDescription.h"

namespace tlmhub::fmu {

const char* causalityName(Causality causality)
{
    switch (causality) {
    case Causality::Parameter: return "parameter";
    case Causality::CalculatedParameter: return "calculatedParameter";
    case Causality::Input: return "input";
    case Causality::Output: return "output";
    case Causality::Local: return "local";
    case Causality::Independent: return "independent";
    }
    return "local";
}

const char* variabilityName(Variability variability)
{
    switch (variability) {
    case Variability::Constant: return "constant";
    case Variability::Fixed: return "fixed";
    case Variability::Tunable: return "tunable";
    case Variability::Discrete: return "discrete";
    case Variability::Continuous: return "continuous";
    }
    return "continuous";
}

const char* variableTypeName(VariableType type)
{
    switch (type) {
    case VariableType::Real: return "Real";
    case VariableType::Integer: return "Integer";
    case VariableType::Boolean: return "Boolean";
    case VariableType::String: return "String";
    }
    return "Real";
}

} // namespace tlmhub::fmu
