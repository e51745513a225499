#include "core/components/signal/Signal3DLookupTable.h"

#include "core/ComponentFactory.h"
#include <algorithm>
#include <cstddef>
#include <vector>

namespace tlmhub {

// Data: 4 columns per line, last line holds the dimension sizes.
bool Signal3DLookupTable::loadTable()
{
    for (int d = 0; d < mTable.getNumDims(); ++d) { mTable.getIndexDataRef(d).clear(); }
    mTable.getValueDataRef().clear();
    const bool useText = !mText.empty();
    CsvDataReader csv;
    bool ok = true;
    if (useText) {
        csv.openText(mText);
    } else {
        ok = csv.openFile(findFilePath(mFilename));
    }
    // numlineskip is clamped but (as in the reference) never handed to the reader.
    mNumlineskip = std::max(mNumlineskip, 0);
    if (ok && !mComment.empty()) {
        if (mComment.size() > 1) {
            addErrorMessage("The comment character must be a single character.");
            ok = false;
        } else {
            csv.setCommentChar(mComment[0]);
        }
    }
    if (ok) { csv.indexFile(); }
    if (!ok) {
        addErrorMessage(useText ? "Unable to read the CSV text: " + csv.getErrorString()
                                : "Unable to read the CSV file: " + mFilename + ", " + csv.getErrorString());
        return false;
    }
    const std::size_t nLines = csv.getNumDataRows();
    bool sameCols = nLines > 0;
    for (std::size_t r = 0; r < nLines; ++r) { sameCols = sameCols && csv.getNumDataCols(r) == 4; }
    if (!sameCols) {
        addErrorMessage("Wrong number of data columns, every line must have 4.");
        return false;
    }
    std::vector<long> sizes;
    if (!csv.copyRow(nLines - 1, sizes) || sizes.size() < 3) {
        addErrorMessage("Could not parse the dimension sizes (last line).");
        return false;
    }

    const std::size_t nR = static_cast<std::size_t>(sizes[0]);
    const std::size_t nC = static_cast<std::size_t>(sizes[1]);
    const std::size_t nP = static_cast<std::size_t>(sizes[2]);
    std::vector<double>& rowIdx = mTable.getIndexDataRef(0);
    bool ok2 = nC > 0 && nP > 0 && csv.copyEveryNthFromColumn(0, nC * nP, rowIdx);
    ok2 = ok2 && csv.copyEveryNthFromColumnRange(1, 0, nC * nP, nP, mTable.getIndexDataRef(1));
    ok2 = ok2 && csv.copyRangeFromColumn(2, 0, nP, mTable.getIndexDataRef(2));
    if (!ok2) {
        addErrorMessage("Could not parse the index columns.");
        return false;
    }
    // The sizes line is picked up by the row stride; drop it.
    if (rowIdx.size() == nR + 1) { rowIdx.pop_back(); }
    if (!csv.copyRangeFromColumn(3, 0, nLines - 1, mTable.getValueDataRef())) {
        addErrorMessage("Could not parse the value column.");
        return false;
    }
    if (nR != mTable.getIndexDataSize(0) || nC != mTable.getIndexDataSize(1) || nP != mTable.getIndexDataSize(2)) {
        addErrorMessage("The extracted number of rows/columns/planes does not match the last line.");
        return false;
    }

    mTable.sortIncreasing();
    if (!mTable.isDataOK()) {
        addErrorMessage("The lookup table data is not OK.");
        if (!mTable.isDataSizeOK()) { addErrorMessage("The index and value vectors have unusable sizes."); }
        if (!mTable.allIndexStrictlyIncreasing()) {
            addErrorMessage("An index column is not strictly increasing, even after sorting.");
        }
        return false;
    }
    return true;
}

void Signal3DLookupTable::configure()
{
    addInputVariable("row", "Row index value", "", 0.0, &mpRow);
    addInputVariable("col", "Column index value", "", 0.0, &mpCol);
    addInputVariable("plane", "Plane index value", "", 0.0, &mpPlane);
    addOutputVariable("out", "Interpolated value", "", &mpOut);
    addConstant("filename", "Data file (absolute or relative to the model file)", std::string(""), mFilename, ParameterType::FilePath);
    addConstant("text", "Data as text (used instead of the file when not empty)", std::string(""), mText, ParameterType::TextBlock);
    addConstant("numlineskip", "Number of lines to skip (has no effect, as in the reference)", "", 0, mNumlineskip);
    addConstant("comment", "Skip leading lines starting with this character", std::string(""), mComment, ParameterType::String);
    addConstant("reload", "Reload the data at every initialisation", true, mReload);
}

void Signal3DLookupTable::initialize()
{
    if (mTable.getValueDataSize() == 0 || mReload) {
        mTableOK = loadTable();
        if (!mTableOK) {
            stopSimulation("Signal3DLookupTable: could not load the table.");
            return;
        }
    }
    simulateOneTimestep();
}

void Signal3DLookupTable::simulateOneTimestep()
{
    if (mTableOK) { *mpOut = mTable.interpolate(*mpRow, *mpCol, *mpPlane); }
}

TLMHUB_REGISTER_COMPONENT(Signal3DLookupTable, "Signal")

} // namespace tlmhub
