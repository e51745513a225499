#include "core/components/signal/Signal1DLookupTable.h"

#include "core/ComponentFactory.h"
#include <algorithm>
#include <cstddef>

namespace tlmhub {

// Reads the two columns into the table; reports and returns false on any problem.
bool Signal1DLookupTable::loadTable()
{
    mTable.getIndexDataRef(0).clear();
    mTable.getValueDataRef().clear();
    const bool useText = !mText.empty();
    CsvDataReader csv;
    bool ok = true;
    if (useText) {
        csv.openText(mText);
    } else {
        ok = csv.openFile(findFilePath(mFilename));
    }
    if (ok) {
        mNumlineskip = std::max(mNumlineskip, 0);
        if (!mComment.empty()) {
            if (mComment.size() > 1) {
                addErrorMessage("The comment character must be a single character.");
                ok = false;
            } else {
                csv.setCommentChar(mComment[0]);
            }
        }
    }
    if (ok) {
        if (mCsvsep.size() == 1) {
            csv.setLinesToSkip(static_cast<std::size_t>(mNumlineskip));
            csv.setFieldSeparator(mCsvsep[0]);
            csv.indexFile();
        } else {
            addErrorMessage("The separator must be a single character.");
            ok = false;
        }
    }
    if (!ok) {
        addErrorMessage(useText ? "Unable to read the CSV text: " + csv.getErrorString()
                                : "Unable to read the CSV file: " + mFilename + ", " + csv.getErrorString());
        return false;
    }

    // Column ids are checked against the widest row.
    std::size_t maxCols = 0;
    for (std::size_t r = 0; r < csv.getNumDataRows(); ++r) { maxCols = std::max(maxCols, csv.getNumDataCols(r)); }
    if (mInid < 0 || mOutid < 0 || mInid >= static_cast<int>(maxCols) || mOutid >= static_cast<int>(maxCols)) {
        addErrorMessage("inid: " + std::to_string(mInid) + " or outid: " + std::to_string(mOutid)
                        + " is out of range.");
        return false;
    }
    ok = csv.copyColumn(static_cast<std::size_t>(mInid), mTable.getIndexDataRef(0));
    ok = ok && csv.copyColumn(static_cast<std::size_t>(mOutid), mTable.getValueDataRef());
    if (!ok) {
        addErrorMessage("Could not parse the index or value column.");
        return false;
    }

    // Sorting is a no-op when the index is already strictly increasing.
    mTable.sortIncreasing();
    if (!mTable.isDataOK()) {
        addErrorMessage("The lookup table data is not OK.");
        if (!mTable.isDataSizeOK()) { addErrorMessage("The index and value vectors have unusable sizes."); }
        if (!mTable.allIndexStrictlyIncreasing()) {
            addErrorMessage("The index column is not strictly increasing, even after sorting.");
        }
        return false;
    }
    return true;
}

void Signal1DLookupTable::configure()
{
    addInputVariable("in", "Index value", "", 0.0, &mpIn);
    addOutputVariable("out", "Interpolated value", "", &mpOut);
    addConstant("filename", "Data file (absolute or relative to the model file)", std::string(""), mFilename, ParameterType::FilePath);
    addConstant("text", "Data as text (used instead of the file when not empty)", std::string(""), mText, ParameterType::TextBlock);
    addConstant("csvsep", "CSV field separator (one character)", std::string(","), mCsvsep, ParameterType::String);
    addConstant("inid", "Index column (0-based)", "", 0, mInid);
    addConstant("outid", "Value column (0-based)", "", 1, mOutid);
    addConstant("numlineskip", "Number of lines to skip at the top", "", 0, mNumlineskip);
    addConstant("comment", "Skip leading lines starting with this character", std::string(""), mComment, ParameterType::String);
    addConstant("reload", "Reload the data at every initialisation", true, mReload);
}

void Signal1DLookupTable::initialize()
{
    if (mTable.getValueDataSize() == 0 || mReload) {
        mTableOK = loadTable();
        if (!mTableOK) {
            stopSimulation("Signal1DLookupTable: could not load the table.");
            return;
        }
    }
    simulateOneTimestep();
}

void Signal1DLookupTable::simulateOneTimestep()
{
    if (mTableOK) { *mpOut = mTable.interpolate(*mpIn); }
}

TLMHUB_REGISTER_COMPONENT(Signal1DLookupTable, "Signal")

} // namespace tlmhub
