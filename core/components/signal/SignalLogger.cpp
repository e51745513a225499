#include "core/components/signal/SignalLogger.h"

#include "core/ComponentFactory.h"
#include "core/System.h"

#include <ctime>
#include <ios>
#include <sstream>

namespace tlmhub {

namespace {

// Comma-separated list; an empty string is an empty list.
std::vector<std::string> splitList(const std::string& s)
{
    std::vector<std::string> out;
    if (s.empty()) return out;
    std::size_t start = 0;
    while (true) {
        const std::size_t pos = s.find(',', start);
        if (pos == std::string::npos) {
            out.push_back(s.substr(start));
            break;
        }
        out.push_back(s.substr(start, pos - start));
        start = pos + 1;
    }
    return out;
}

// Default stream formatting (6 significant digits) for the row-wise CSV cells.
std::string numberText(double v)
{
    std::ostringstream ss;
    ss << v;
    return ss.str();
}

std::string scientificText(double v)
{
    std::ostringstream ss;
    ss << std::scientific << v;
    return ss.str();
}

} // namespace

void SignalLogger::configure()
{
    mpIn = addReadMultiPort("in", NodeType::Signal, false);
    addConstant("path", "Path to the log file to write", "", mPath, ParameterType::FilePath);
    addConditionalConstant("filetype", "File type",
                           {"Plain column-wise CSV", "Plain row-wise CSV", "Hopsan column-wise CSV",
                            "Hopsan PLO"},
                           0, mFileType);
    addInputVariable("dt", "Logging interval (0 = every sample)", "s", 0.0, &mpDt);
    addConstant("names", "Variable names (comma separated)", "", mNames);
    addConstant("aliases", "Variable aliases (comma separated)", "", mAliases);
    addConstant("units", "Variable units (comma separated)", "", mUnits);
}

void SignalLogger::initialize()
{
    mReady = false;
    mRows.clear();
    if (mFile.is_open()) mFile.close();

    const std::size_t numVars = getNumPorts(mpIn);
    mInData.clear();
    for (std::size_t i = 0; i < numVars; ++i) {
        mInData.push_back(getSafeMultiPortNodeDataPtr(mpIn, i, NodeSignal::Value));
    }

    const std::vector<std::string> names = splitList(mNames);
    const std::vector<std::string> aliases = splitList(mAliases);
    const std::vector<std::string> units = splitList(mUnits);
    if (names.size() != numVars) {
        stopSimulation("Number of variable names must equal number of input variables");
        return;
    }
    if (mFileType == HopsanRowWiseCsv && aliases.size() != numVars) {
        stopSimulation("Number of variable aliases must equal number of input variables");
        return;
    }
    if (mFileType == HopsanRowWiseCsv && units.size() != numVars) {
        stopSimulation("Number of variable units must equal number of input variables");
        return;
    }

    const std::string path = findFilePath(mPath);
    mFile.open(path, std::ios::out | std::ios::trunc);
    if (!mFile.is_open()) {
        stopSimulation("Could not open file for writing: " + path);
        return;
    }

    if (mFileType == PlainColumnWiseCsv) {
        mFile << "Time";
        for (const std::string& n : names) mFile << "," << n;
        mFile << "\n";
    } else if (mFileType == PlainRowWiseCsv) {
        mRows.push_back("Time");
        for (const std::string& n : names) mRows.push_back(n);
    } else if (mFileType == HopsanRowWiseCsv) {
        mRows.push_back("Time,,");
        for (std::size_t i = 0; i < numVars; ++i) {
            mRows.push_back(names[i] + "," + aliases[i] + "," + units[i]);
        }
    } else if (mFileType == HopsanPlo) {
        // File name = last path component (either separator).
        std::string fileName = mPath;
        const std::size_t sep = fileName.find_last_of("/\\");
        if (sep != std::string::npos) fileName = fileName.substr(sep + 1);
        const std::string modelName = parentSystem() ? parentSystem()->name() : std::string();

        char timeText[100] = {};
        const std::time_t now = std::time(nullptr);
        if (const std::tm* local = std::localtime(&now)) {
            std::strftime(timeText, sizeof(timeText), "%a %b %d %H:%M:%S %Y", local);
        }

        mRows.push_back("    'VERSION'");
        mRows.push_back("    3");
        mRows.push_back("    '" + fileName + "' '" + modelName + "' '" + timeText + "' 'tlmhub'");
        mRows.push_back("");  // "columns rows", filled in by finalize()
        std::string header = "    'Time'";
        for (const std::string& n : names) header += ",    '" + n + "'";
        mRows.push_back(header);
        std::string scales = "  Time";
        for (std::size_t i = 0; i < numVars; ++i) scales += " 1";
        mRows.push_back(scales);
    }

    mReady = true;
    // Log the t0 sample too.
    mLastLogTime = mTime - *mpDt;
    simulateOneTimestep();
}

void SignalLogger::simulateOneTimestep()
{
    if (!mReady) return;
    if (mTime < mLastLogTime + *mpDt) return;
    mLastLogTime = mTime;

    const std::size_t numVars = mInData.size();
    if (mFileType == PlainColumnWiseCsv) {
        mFile << mTime;
        for (std::size_t i = 0; i < numVars; ++i) mFile << "," << *mInData[i];
        mFile << "\n";
    } else if (mFileType == PlainRowWiseCsv || mFileType == HopsanRowWiseCsv) {
        mRows[0] += ',';
        mRows[0] += numberText(mTime);
        for (std::size_t i = 0; i < numVars; ++i) {
            mRows[i + 1] += ',';
            mRows[i + 1] += numberText(*mInData[i]);
        }
    } else if (mFileType == HopsanPlo) {
        std::string row = "  " + scientificText(mTime);
        for (std::size_t i = 0; i < numVars; ++i) {
            const double v = *mInData[i];
            row += (v < 0.0) ? " " : "  ";
            row += scientificText(v);
        }
        mRows.push_back(row);
    }
}

void SignalLogger::finalize()
{
    if (!mReady) return;
    if (mFileType == HopsanPlo) {
        // Row count quirk kept: all collected lines minus one (data rows + 5).
        mRows[3] = "    " + std::to_string(mInData.size() + 1) + "    " + std::to_string(mRows.size() - 1);
    }
    if (mFileType != PlainColumnWiseCsv) {
        for (const std::string& row : mRows) mFile << row << "\n";
    }
    mFile.close();
    mReady = false;
}

TLMHUB_REGISTER_COMPONENT(SignalLogger, "Signal")

} // namespace tlmhub
