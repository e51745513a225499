#pragma once
// Files the server tests read: the shared models in place (never copied), and any file whole.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace tlmhub::test {

inline const std::filesystem::path kSharedDir = std::filesystem::path(TLMHUB_SOURCE_DIR) / ".." / "shared";
inline const std::filesystem::path kExampleModels = kSharedDir / "hopsan-models" / "Example Models";
inline const std::filesystem::path kPositionServo = kExampleModels / "Position Servo.hmf";
// A model to export as an FMU: input u through a gain to output y, and a hydraulic line.
inline const std::filesystem::path kFmuGain = std::filesystem::path(TLMHUB_SOURCE_DIR) / "tests/server/data/FmuGain.hmf";
// Divide#out#Value = Divide.in1 / round(Round.in): a run fails (division by zero) when
// |Round.in| < 0.5, so a study can have failing runs where it chooses.
inline const std::filesystem::path kRoundDivide = std::filesystem::path(TLMHUB_SOURCE_DIR) / "tests/server/data/RoundDivide.hmf";

// The whole file; a file that cannot be read fails the test (and gives "").
inline std::string readFile(const std::filesystem::path& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) ADD_FAILURE() << "cannot read " << path;
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

} // namespace tlmhub::test
