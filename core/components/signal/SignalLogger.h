#pragma once
#include "core/Component.h"

#include <fstream>
#include <string>
#include <vector>

namespace tlmhub {

// Writes the signals connected to `in` to a text file (CSV or PLO) during the run.
// It has no outputs and no effect on results. File output necessarily allocates while
// stepping (rows are kept in memory for the row-wise formats).
class SignalLogger : public ComponentSignal {
public:
    void configure() override;
    void initialize() override;
    void simulateOneTimestep() override;
    void finalize() override;

private:
    enum FileType { PlainColumnWiseCsv = 0, PlainRowWiseCsv = 1, HopsanRowWiseCsv = 2, HopsanPlo = 3 };

    Port* mpIn = nullptr;
    double* mpDt = nullptr;
    std::string mPath;
    std::string mNames;
    std::string mAliases;
    std::string mUnits;
    int mFileType = PlainColumnWiseCsv;

    std::ofstream mFile;
    std::vector<double*> mInData;
    std::vector<std::string> mRows;
    double mLastLogTime = 0.0;
    bool mReady = false;
};

} // namespace tlmhub
