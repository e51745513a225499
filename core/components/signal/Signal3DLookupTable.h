#pragma once
#include "core/Component.h"
#include "core/numerics/LookupTable.h"
#include "core/numerics/CsvDataReader.h"

#include <string>

namespace tlmhub {

// Three-dimensional lookup table (trilinear, inputs clamped) from CSV lines
// "row, col, plane, value" plus a final "nRows, nCols, nPlanes, x" line.
class Signal3DLookupTable : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;

private:
    double* mpRow = nullptr;
    double* mpCol = nullptr;
    double* mpPlane = nullptr;
    double* mpOut = nullptr;
    std::string mFilename;
    std::string mText;
    int mNumlineskip = 0;
    std::string mComment;
    bool mReload = true;
    LookupTable3D mTable;
    bool mTableOK = false;
    bool loadTable();
};

} // namespace tlmhub
