#include "core/components/signal/Signal1DPLOLookupTable.h"

#include "core/ComponentFactory.h"
#include "core/numerics/PloDataReader.h"

namespace tlmhub {

bool Signal1DPLOLookupTable::loadTable()
{
    mTable.getIndexDataRef(0).clear();
    mTable.getValueDataRef().clear();
    PloDataReader plo;
    const bool ok = mText.empty() ? plo.readFile(findFilePath(mFilename)) : plo.readText(mText);
    if (!ok) {
        addErrorMessage("Could not read the PLO data: " + plo.getErrorString());
        return false;
    }
    if (plo.findColumn(mInvar) < 0) {
        addErrorMessage("Variable " + mInvar + " not found in the PLO data.");
        return false;
    }
    if (plo.findColumn(mOutvar) < 0) {
        addErrorMessage("Variable " + mOutvar + " not found in the PLO data.");
        return false;
    }
    if (!plo.copyColumn(mInvar, mTable.getIndexDataRef(0)) || !plo.copyColumn(mOutvar, mTable.getValueDataRef())) {
        addErrorMessage("Could not copy the PLO columns.");
        return false;
    }
    mTable.sortIncreasing();
    if (!mTable.isDataOK()) {
        addErrorMessage("The lookup table data is not OK (sizes, or index not strictly increasing).");
        return false;
    }
    return true;
}

void Signal1DPLOLookupTable::configure()
{
    addInputVariable("in", "Index value", "", 0.0, &mpIn);
    addOutputVariable("out", "Interpolated value", "", &mpOut);
    addConstant("filename", "PLO file (absolute or relative to the model file)", std::string(""), mFilename, ParameterType::FilePath);
    addConstant("text", "PLO data as text (used instead of the file when not empty)", std::string(""), mText, ParameterType::TextBlock);
    addConstant("invar", "Name of the index column", std::string("Time"), mInvar, ParameterType::String);
    addConstant("outvar", "Name of the value column", std::string("Data"), mOutvar, ParameterType::String);
    addConstant("reload", "Reload the data at every initialisation", true, mReload);
}

void Signal1DPLOLookupTable::initialize()
{
    if (mTable.getValueDataSize() == 0 || mReload) {
        mTableOK = loadTable();
        if (!mTableOK) {
            stopSimulation("Signal1DPLOLookupTable: could not load the table.");
            return;
        }
    }
    simulateOneTimestep();
}

void Signal1DPLOLookupTable::simulateOneTimestep()
{
    if (mTableOK) { *mpOut = mTable.interpolate(*mpIn); }
}

TLMHUB_REGISTER_COMPONENT(Signal1DPLOLookupTable, "Signal")

} // namespace tlmhub
