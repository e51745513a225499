#include "core/components/mechanic/CombustionEngine.h"

#include "core/ComponentFactory.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"
#include "core/numerics/CsvDataReader.h"

namespace tlmhub {

void CombustionEngine::configure()
{
    addConstant("P_max", "Maximum power", "W", 150000.0, mPMax);
    // Hopsan's default names the curve shipped with its installation; a model that keeps
    // it needs that file next to the path it resolves to.
    addConstant("Characteristics", "Torque-speed characteristics (CSV: speed, maximum torque)",
                std::string("../componentLibraries/defaultLibrary/Special/CombustionEngine.csv"), mCharacteristics,
                ParameterType::FilePath);
    mpIn = addReadPort("in", NodeType::Signal);
    setDefaultStartValue(mpIn, NodeSignal::Value, 0.0);
    mpP1 = addPowerPort("P1", NodeType::MechanicRotational);
}

bool CombustionEngine::loadCurve()
{
    mMaxTorque.getIndexDataRef(0).clear();
    mMaxTorque.getValueDataRef().clear();
    CsvDataReader csv;
    if (!csv.openFile(findFilePath(mCharacteristics))) {
        addErrorMessage("Unable to read the CSV file: " + mCharacteristics + ", " + csv.getErrorString());
        return false;
    }
    csv.indexFile();
    if (!csv.copyColumn(0, mMaxTorque.getIndexDataRef(0)) || !csv.copyColumn(1, mMaxTorque.getValueDataRef())) {
        addErrorMessage("Could not read the speed and torque columns of " + mCharacteristics);
        return false;
    }
    mMaxTorque.sortIncreasing();
    if (!mMaxTorque.isDataOK()) {
        addErrorMessage("The speed column of " + mCharacteristics + " is not strictly increasing, even after sorting");
        return false;
    }
    return true;
}

void CombustionEngine::initialize()
{
    mpThrottle = getSafeNodeDataPtr(mpIn, NodeSignal::Value);
    mpP1_w = getSafeNodeDataPtr(mpP1, NodeMechanicRotational::AngularVelocity);
    mpP1_c = getSafeNodeDataPtr(mpP1, NodeMechanicRotational::WaveVariable);
    mpP1_Zc = getSafeNodeDataPtr(mpP1, NodeMechanicRotational::CharImpedance);
    if (!loadCurve()) {
        stopSimulation("CombustionEngine: could not load the torque curve.");
        return;
    }
    *mpP1_c = 0.0;
    *mpP1_Zc = 0.0;
}

void CombustionEngine::simulateOneTimestep()
{
    const double w = *mpP1_w;
    // Speed is negative when the engine drives its load (the node's sign convention), so
    // the requested torque -in * P_max / w is positive then; the curve is looked up at w.
    *mpP1_c = limit(-*mpThrottle * mPMax / w, 0.0, mMaxTorque.interpolate(w));
    *mpP1_Zc = 0.0;
}

TLMHUB_REGISTER_COMPONENT(CombustionEngine, "Mechanic")

} // namespace tlmhub
