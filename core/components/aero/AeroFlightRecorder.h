#pragma once
#include "core/Component.h"

#include <fstream>
#include <string>

namespace tlmhub {

// Writes the flight path as a KML file (Google Earth); no influence on the simulation.
class AeroFlightRecorder : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;
    void finalize() override;

private:
    double *mpLongitude = nullptr, *mpLatitude = nullptr, *mpAltitude = nullptr, *mpPhi = nullptr,
           *mpTheta = nullptr, *mpPsi = nullptr, *mpV = nullptr, *mpDt = nullptr, *mpScaleX = nullptr,
           *mpScaleY = nullptr, *mpScaleZ = nullptr;
    int mFileType = 0;
    std::string mPath, mDaeModel;
    std::ofstream mFile;
    double mLastLogTime = 0.0;
};

} // namespace tlmhub
