#pragma once
// Reading logged results by Hopsan's names (core.md §1.8, §4.4, §4.5).
#include "core/Status.h"
#include "core/System.h"

#include <string>
#include <vector>

namespace tlmhub {

struct LoggedVariable {
    std::string fullName;   // "Sub1$Comp#Port#Var"
    std::string unit;
    const Port* port = nullptr;
    int slot = 0;
    std::size_t count = 0;  // samples written (log counter of the component's system)
    const System* owner = nullptr;  // the component's system; owner->numLoggedSamples() is
                                    // the live count while a run is going on
};

// Every logged port variable in HopsanCLI's export order: sub-components by name, ports by
// name, slots in storage order; subsystem content right after the subsystem.
std::vector<LoggedVariable> listLoggedVariables(const System& root);

// Data of a logged port variable (empty if not logged) and its time vector.
std::vector<double> loggedData(const Port& port, int slot, std::size_t count);
const std::vector<double>* loggedTime(const Port& port);
// Samples [from, to) of a logged port variable appended to `out`, read straight from the log
// buffer (for streaming a run in progress without copying what was already sent). The range
// is clipped to the buffer.
void appendLoggedData(const Port& port, int slot, std::size_t from, std::size_t to,
                      std::vector<double>& out);

// First non-finite value (NaN or infinity) among the logged data and the current node values;
// false if everything is finite, else true with `where` naming the variable (and time).
bool findNonFinite(const System& root, std::string& where);

// Resolve "[Sys$...]Comp#Port#Var" from the root, with the .hvc lookup quirk of core.md §7.3.
struct VariableRef {
    Port* port;
    int slot;   // index of the variable in the port's node
};
Result<VariableRef> resolveVariable(System& root, const std::string& fullName);

} // namespace tlmhub
