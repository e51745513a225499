#include "core/components/mechanic/MechanicThetaSource.h"

#include "core/ComponentFactory.h"

namespace tlmhub {

void MechanicThetaSource::configure()
{
    mpThetaPort = addInputVariable("thetain", "Angle", "rad", 0.0, &mpTheta);
    addInputVariable("omega", "Angular velocity", "rad/s", 0.0, &mpOmega);
    mpPmr1 = addPowerPort("Pmr1", NodeType::MechanicRotational);
}

void MechanicThetaSource::initialize()
{
    mpPmr1_T = getSafeNodeDataPtr(mpPmr1, NodeMechanicRotational::Torque);
    mpPmr1_a = getSafeNodeDataPtr(mpPmr1, NodeMechanicRotational::Angle);
    mpPmr1_w = getSafeNodeDataPtr(mpPmr1, NodeMechanicRotational::AngularVelocity);
    mpPmr1_c = getSafeNodeDataPtr(mpPmr1, NodeMechanicRotational::WaveVariable);
    mpPmr1_Zc = getSafeNodeDataPtr(mpPmr1, NodeMechanicRotational::CharImpedance);

    mThetaConnected = mpThetaPort->isConnected();
    if (mThetaConnected) {
        addWarningMessage("thetain is connected: the angle input is used directly, make sure it "
                          "is consistent with omega.");
    }

    const double w = *mpOmega;
    const double theta = *mpTheta;
    mIntegrator.initialize(mTimestep, w, theta);

    *mpPmr1_T = (*mpPmr1_c) + (*mpPmr1_Zc) * w;
    *mpPmr1_a = theta;
    *mpPmr1_w = w;
}

void MechanicThetaSource::simulateOneTimestep()
{
    const double c = *mpPmr1_c;
    const double Zc = *mpPmr1_Zc;
    const double w = *mpOmega;

    double theta;
    if (mThetaConnected) {
        theta = *mpTheta;
    } else {
        theta = mIntegrator.update(w);
    }

    *mpPmr1_T = c + Zc * w;
    *mpPmr1_a = theta;
    *mpPmr1_w = w;
}

TLMHUB_REGISTER_COMPONENT(MechanicThetaSource, "Mechanic")

} // namespace tlmhub
