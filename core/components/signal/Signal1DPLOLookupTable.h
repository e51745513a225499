#pragma once
#include "core/Component.h"
#include "core/numerics/LookupTable.h"

#include <string>

namespace tlmhub {

// One-dimensional lookup table whose data comes from a Hopsan PLO file or text;
// the index and value columns are chosen by variable name.
class Signal1DPLOLookupTable : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpIn = nullptr;
    double* mpOut = nullptr;
    std::string mFilename;
    std::string mText;
    std::string mInvar;
    std::string mOutvar;
    bool mReload = true;
    LookupTable1D mTable;
    bool mTableOK = false;
    bool loadTable();
};

} // namespace tlmhub
