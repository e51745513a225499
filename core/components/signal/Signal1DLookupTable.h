#pragma once
#include "core/Component.h"
#include "core/numerics/LookupTable.h"
#include "core/numerics/CsvDataReader.h"

#include <string>

namespace tlmhub {

// One-dimensional lookup table (linear interpolation, constant outside the range)
// read from a CSV file or inline text.
class Signal1DLookupTable : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpIn = nullptr;
    double* mpOut = nullptr;
    std::string mFilename;
    std::string mText;
    std::string mCsvsep;
    int mInid = 0;
    int mOutid = 1;
    int mNumlineskip = 0;
    std::string mComment;
    bool mReload = true;
    LookupTable1D mTable;
    bool mTableOK = false;
    bool loadTable();
};

} // namespace tlmhub
