#pragma once
#include "core/Component.h"

#include <deque>
#include <memory>
#include <string>

namespace mu {
class Parser;
}

namespace tlmhub {

// S-type block whose output is computed by a NumHop script (file `scriptfile`),
// evaluated once per step. The script is translated once in initialize() into a
// muParser expression list bound to `in`, `out` and the script-local variables.
class SignalNumHopSISO : public ComponentSignal {
public:
    SignalNumHopSISO();
    ~SignalNumHopSISO() override;
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    bool evaluateScript();

    double* mpIn = nullptr;
    double* mpOut = nullptr;
    std::string mScriptFile;

    // Values muParser reads and writes; `in`/`out` are copied to/from the nodes.
    double mIn = 0.0, mOut = 0.0;
    std::deque<double> mStorage; // stable addresses for locals and resolved names
    std::unique_ptr<mu::Parser> mpParser;
};

} // namespace tlmhub
