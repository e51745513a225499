#include "core/components/signal/SignalLookUpTable2D.h"

#include "core/ComponentFactory.h"
#include "core/numerics/CsvDataReader.h"

#include <algorithm>

namespace tlmhub {

bool SignalLookUpTable2D::loadTable()
{
    mTable.getIndexDataRef(0).clear();
    mTable.getValueDataRef().clear();
    if (mCsvsep.size() != 1) {
        addErrorMessage("The separator must be a single character.");
        return false;
    }
    CsvDataReader csv;
    if (!csv.openFile(findFilePath(mFilename))) {
        addErrorMessage("Unable to read the CSV file: " + mFilename + ", " + csv.getErrorString());
        return false;
    }
    csv.setFieldSeparator(mCsvsep[0]);
    csv.indexFile();

    std::size_t maxCols = 0;
    for (std::size_t r = 0; r < csv.getNumDataRows(); ++r) maxCols = std::max(maxCols, csv.getNumDataCols(r));
    if (mOutid < 0 || mOutid >= static_cast<int>(maxCols)) {
        addErrorMessage("outid: " + std::to_string(mOutid) + " is out of range.");
        return false;
    }
    if (!csv.copyColumn(0, mTable.getIndexDataRef(0)) ||
        !csv.copyColumn(static_cast<std::size_t>(mOutid), mTable.getValueDataRef())) {
        addErrorMessage("Could not parse the index or value column.");
        return false;
    }
    mTable.sortIncreasing();
    if (!mTable.isDataOK()) {
        addErrorMessage("The lookup table data is not OK (sizes, or an index that is not strictly increasing).");
        return false;
    }
    return true;
}

void SignalLookUpTable2D::configure()
{
    addInputVariable("in", "Index value", "", 0.0, &mpIn);
    addOutputVariable("out", "Interpolated value", "", &mpOut);
    addConstant("filename", "Data file (absolute or relative to the model file)", std::string(""), mFilename,
                ParameterType::FilePath);
    addConstant("csvsep", "CSV field separator (one character)", std::string(","), mCsvsep, ParameterType::String);
    addConstant("outid", "Value column (0-based; the index is column 0)", "", 1, mOutid);
    addConstant("reload", "Reload the file at every initialisation", true, mReload);
}

void SignalLookUpTable2D::initialize()
{
    if (mTable.getValueDataSize() == 0 || mReload) {
        mTableOK = loadTable();
        if (!mTableOK) {
            stopSimulation("SignalLookUpTable2D: could not load the table.");
            return;
        }
    }
    simulateOneTimestep();
}

void SignalLookUpTable2D::simulateOneTimestep()
{
    if (mTableOK) *mpOut = mTable.interpolate(*mpIn);
}

TLMHUB_REGISTER_COMPONENT(SignalLookUpTable2D, "Signal")

} // namespace tlmhub
