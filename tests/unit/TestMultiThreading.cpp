// Multi-threaded simulation gives bitwise the same logs as the single-threaded loop.
#include "TestHelpers.h"

#include "core/Results.h"
#include "core/hmf/HmfLoader.h"

#include <filesystem>

using namespace tlmhub;
using namespace tlmhub::test;

namespace {

std::vector<std::vector<double>> simulateWith(const std::string& path, unsigned threads)
{
    LoadedModel m = loadHmfFile(path);
    EXPECT_FALSE(m.hasErrors()) << m.firstError();
    if (m.hasErrors()) return {};
    System& root = *m.root;
    std::string err;
    EXPECT_TRUE(root.checkModel(err)) << err;
    EXPECT_TRUE(root.initialize(root.startTime, root.stopTime));
    EXPECT_TRUE(root.simulateMultiThreaded(root.stopTime, threads));
    root.finalize();
    std::vector<std::vector<double>> out{root.logTime()};
    for (const auto& v : listLoggedVariables(root)) out.push_back(loggedData(*v.port, v.slot, v.count));
    return out;
}

class MultiThreading : public ::testing::TestWithParam<const char*> {};

} // namespace

TEST_P(MultiThreading, LogsAreBitwiseEqualToSingleThreaded)
{
    const std::string path = sharedDir() + "/hopsan-models/" + GetParam();
    if (!std::filesystem::exists(path)) GTEST_SKIP() << "shared models not present";
    const auto single = simulateWith(path, 1);
    ASSERT_GT(single.size(), 1u);
    for (unsigned threads : {2u}) {
        const auto multi = simulateWith(path, threads);
        ASSERT_EQ(single.size(), multi.size());
        for (std::size_t i = 0; i < single.size(); ++i)
            ASSERT_EQ(single[i], multi[i]) << "column " << i << " with " << threads << " threads";
    }
}

INSTANTIATE_TEST_SUITE_P(ValidationModels, MultiThreading,
                         ::testing::Values("Example Models/Position Servo.hmf",
                                           "Example Models/Sub System Example.hmf",
                                           "Example Models/Dynamic Pressure Feedback.hmf",
                                           "Example Models/Pressure Relief Valve Characteristics.hmf",
                                           "Example Models/In-Line Axial Piston Machine.hmf",
                                           "Component Test/HydraulicComponent Test/HydraulicLineTest.hmf"));
