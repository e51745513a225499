#pragma once
#include "core/Component.h"
#include "core/numerics/LookupTable.h"
#include "core/numerics/CsvDataReader.h"

#include <string>

namespace tlmhub {

// Two-dimensional lookup table (bilinear, inputs clamped to the table range) from
// CSV lines "row, col, value" plus a final "nRows, nCols, x" line.
class Signal2DLookupTable : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpRow = nullptr;
    double* mpCol = nullptr;
    double* mpOut = nullptr;
    std::string mFilename;
    std::string mText;
    int mNumlineskip = 0;
    std::string mComment;
    bool mReload = true;
    LookupTable2D mTable;
    bool mTableOK = false;
    bool loadTable();
};

} // namespace tlmhub
