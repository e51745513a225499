#include "core/components/aero/AeroFlightRecorder.h"

#include "core/ComponentFactory.h"
#include "core/System.h"
#include "core/numerics/AuxiliarySimulationFunctions.h"

namespace tlmhub {

namespace {
enum FileType { FlightPath = 0, GroundPath = 1, Vehicle3D = 2 };
}

void AeroFlightRecorder::configure()
{
    addInputVariable("longitude", "Longitude E", "deg", 15.577, &mpLongitude);
    addInputVariable("latitude", "Latitude N", "deg", 58.401, &mpLatitude);
    addInputVariable("altitude", "Altitude above MSL", "m", 0.0, &mpAltitude);
    addInputVariable("phi", "Roll", "rad", 0.0, &mpPhi);
    addInputVariable("theta", "Pitch", "rad", 0.0, &mpTheta);
    addInputVariable("psi", "Heading", "rad", 0.0, &mpPsi);
    addInputVariable("v", "Speed", "m/s", 0.0, &mpV);
    addInputVariable("dt", "Logging interval (0 = log every sample)", "s", 1.0, &mpDt);
    addInputVariable("scaleX", "X-axis scaling factor for .dae 3D model", "", 1.0, &mpScaleX);
    addInputVariable("scaleY", "Y-axis scaling factor for .dae 3D model", "", 1.0, &mpScaleY);
    addInputVariable("scaleZ", "Z-axis scaling factor for .dae 3D model", "", 1.0, &mpScaleZ);
    addConditionalConstant("filetype", "Output file type", {"Flight path KML", "Ground path KML", "3D vehicle KML"},
                           0, mFileType);
    addConstant("path", "Path where the output file should be placed", "", mPath);
    addConstant("daeModel", "File path to a .dae model for 3D vehicle representation", "", mDaeModel);
    // Read in initialize() only: a new value needs a new start.
    setLiveChangeable({"v"}, false);
}

void AeroFlightRecorder::initialize()
{
    // Same failure as Hopsan when no output directory is given.
    if (mPath.empty()) {
        stopSimulation("Please specify a path for the output file.");
        return;
    }
    if (mFileType == Vehicle3D && mDaeModel.empty()) {
        stopSimulation("A 3D vehicle KML is requested but no .dae model has been specified.");
        return;
    }
    const std::string modelName = parentSystem() ? parentSystem()->name() : name();
    const std::string fileName = mPath + "/" + modelName + ".kml";
    mFile.open(fileName);
    if (!mFile.is_open()) {
        stopSimulation("Could not open the output file: " + fileName);
        return;
    }
    mFile << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<kml>\n<Document>\n  <Folder>\n    <name>SimResults</name>\n";
    if (mFileType == FlightPath || mFileType == GroundPath) {
        mFile << "    <Placemark>\n      <name>" << (mFileType == FlightPath ? "Flight Path" : "Ground Path")
              << "</name>\n      <LineString>\n        <altitudeMode>"
              << (mFileType == FlightPath ? "absolute" : "clampToGround") << "</altitudeMode>\n        <coordinates>\n";
    }
    mLastLogTime = mTime - *mpDt;
    simulateOneTimestep();
}

void AeroFlightRecorder::simulateOneTimestep()
{
    if (!mFile.is_open() || mTime < mLastLogTime + *mpDt) { return; }
    mLastLogTime = mTime;
    const double lon = *mpLongitude, lat = *mpLatitude, alt = *mpAltitude;
    if (mFileType == FlightPath || mFileType == GroundPath) {
        mFile << "          " << lon << "," << lat << "," << alt << "\n";
    } else {
        mFile << "    <Placemark>\n      <name>Time" << mTime << "s</name>\n      <Model>\n"
              << "        <altitudeMode>absolute</altitudeMode>\n"
              << "        <Location><latitude>" << lat << "</latitude><longitude>" << lon
              << "</longitude><altitude>" << alt << "</altitude></Location>\n"
              << "        <Orientation><heading>" << rad2deg(*mpPsi) << "</heading><tilt>" << -rad2deg(*mpTheta)
              << "</tilt><roll>" << -rad2deg(*mpPhi) << "</roll></Orientation>\n"
              << "        <Scale><x>" << *mpScaleY << "</x><y>" << *mpScaleX << "</y><z>" << *mpScaleZ
              << "</z></Scale>\n"
              << "        <Link><href>" << mDaeModel << "</href></Link>\n      </Model>\n    </Placemark>\n";
    }
}

void AeroFlightRecorder::finalize()
{
    if (!mFile.is_open()) { return; }
    if (mFileType == FlightPath || mFileType == GroundPath) {
        mFile << "        </coordinates>\n      </LineString>\n    </Placemark>\n";
    }
    mFile << "  </Folder>\n</Document>\n</kml>\n";
    mFile.close();
}

TLMHUB_REGISTER_COMPONENT(AeroFlightRecorder, "Aero")

} // namespace tlmhub
