#pragma once
// Parameters: named value strings evaluated into component variables (core.md §5).
#include <memory>
#include <string>
#include <vector>

namespace tlmhub {

enum class ParameterType { Double, Integer, Bool, String, TextBlock, FilePath, Conditional };

const char* parameterTypeName(ParameterType type);
bool parameterTypeFromName(const std::string& name, ParameterType& out);

struct Parameter {
    std::string name;
    std::string description;
    std::string unit;
    ParameterType type = ParameterType::Double;
    std::string value;          // the value string as stored in the model
    std::string defaultValue;   // value string at registration
    bool isStartValue = false;  // Port#Variable parameters
    bool internal = false;      // system parameters only
    // A running simulation may take a new value between two steps (Simulation::
    // changeWhileRunning). Set where the component type registers it, for the start value of
    // a variable whose node the component reads every step (an input variable by default).
    bool liveChangeable = false;
    std::vector<std::string> conditions;  // alternatives of a conditional parameter

    // Where evaluation writes the number/string. Exactly one is set for component
    // parameters; system parameters point at their own storage below.
    double* doubleTarget = nullptr;
    int* intTarget = nullptr;
    bool* boolTarget = nullptr;
    std::string* stringTarget = nullptr;

    // Own storage for system parameters.
    double ownDouble = 0.0;
    int ownInt = 0;
    bool ownBool = false;
    std::string ownString;
    void bindOwnStorage();
};

// Parameters in registration order; names unique.
class ParameterSet {
public:
    Parameter* find(const std::string& name);
    const Parameter* find(const std::string& name) const;
    Parameter& add(Parameter p);
    bool remove(const std::string& name);
    bool rename(const std::string& oldName, const std::string& newName);
    const std::vector<std::unique_ptr<Parameter>>& all() const { return mParameters; }

private:
    std::vector<std::unique_ptr<Parameter>> mParameters;
};

// Number formatting used for parameter strings: the shortest form that reads back as the
// same double.
std::string formatNumber(double value);

} // namespace tlmhub
