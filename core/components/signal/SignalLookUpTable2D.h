#pragma once
#include "core/Component.h"
#include "core/numerics/LookupTable.h"

#include <string>

namespace tlmhub {

// Hopsan's obsolete "LookUpTable2D": despite the name a one-dimensional table, index in
// column 0 and value in column `outid` of a CSV file; linear interpolation, constant outside.
class SignalLookUpTable2D : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    bool loadTable();

    double* mpIn = nullptr;
    double* mpOut = nullptr;
    std::string mFilename;
    std::string mCsvsep;
    int mOutid = 1;
    bool mReload = true;
    LookupTable1D mTable;
    bool mTableOK = false;
};

} // namespace tlmhub
