#pragma once
// One table of legacy names found in old Hopsan model files (core.md §6.4): obsolete or
// misspelt type names, renamed ports and renamed parameters.
#include <string>

namespace tlmhub::legacy {

// Version of the core that saved a file, as Hopsan compares them.
struct CoreVersion {
    std::string text;
    // True when Hopsan's core refuses the file (older than 0.6.0, or a 0.6.x_rNNNN
    // development build below r5500). We load such files with the GUI's full renames.
    bool refusedByHopsanCore() const;
    // True for files older than 0.6.0 or any "0.6.x_r" build: parameter names with '::'.
    bool usesOldParameterNames() const;
};

// Current type name for `typeName` (unchanged if it is not a legacy name).
std::string currentTypeName(const std::string& typeName);
// Current port name of a renamed port of `typeName` (as given, if not renamed).
std::string currentPortName(const std::string& typeName, const std::string& portName,
                            bool fullRenames);
// Parameter name rewrite of the core loader (`::` -> `#`, `sigma^2` -> `std_dev`, blanks),
// plus, with fullRenames, the GUI's variable and parameter renames.
std::string currentParameterName(const std::string& typeName, const std::string& parameterName,
                                 const CoreVersion& version);

} // namespace tlmhub::legacy
