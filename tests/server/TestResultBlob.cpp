// Stored results (server/store/ResultBlob): compressed column by column, every value back
// exactly, one variable read without the others, results stored before (version 1) still
// read, damaged blobs refused.
#include "core/ResultTable.h"
#include "core/Simulation.h"
#include "core/hmf/HmfLoader.h"
#include "server/store/ResultBlob.h"
#include "TestFiles.h"

#include <gtest/gtest.h>

#include <cstring>
#include <iostream>

using namespace tlmhub;
using namespace tlmhub::server;

namespace {

const std::string kServo =
    std::string(TLMHUB_SOURCE_DIR) + "/../shared/hopsan-models/Example Models/Position Servo.hmf";

bool bitwiseEqual(const std::vector<double>& a, const std::vector<double>& b)
{
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

// A finished run of Position Servo, kept for the view.
struct ServoRun {
    ServoRun()
    {
        model = loadHmfString(test::readFile(kServo), "", "servo");
        EXPECT_FALSE(model.hasErrors()) << model.firstError();
        Result<Simulation> compiled = compile(*model.root, {});
        EXPECT_TRUE(compiled) << compiled.status().message();
        sim.emplace(std::move(*compiled));
        const Status ran = sim->run();
        EXPECT_TRUE(ran) << ran.message();
    }
    LoadedModel model;
    std::optional<Simulation> sim;
};

void expectSameTable(const ResultTable& a, const ResultTable& b)
{
    EXPECT_TRUE(bitwiseEqual(a.time, b.time));
    ASSERT_EQ(a.columns.size(), b.columns.size());
    for (std::size_t i = 0; i < a.columns.size(); ++i) {
        EXPECT_EQ(a.columns[i].name, b.columns[i].name);
        EXPECT_EQ(a.columns[i].unit, b.columns[i].unit);
        EXPECT_TRUE(bitwiseEqual(a.columns[i].data, b.columns[i].data)) << a.columns[i].name;
    }
}

} // namespace

TEST(ResultBlob, EveryValueComesBackExactlyFromUnderAThirdOfTheBytes)
{
    ServoRun run;
    const ResultView view = run.sim->results();
    const ResultTable direct = ResultTable::fromView(view);
    const std::string blob = encodeResult(view);
    EXPECT_EQ(uncompressedResultBytes(view), direct.byteSize());
    EXPECT_LT(blob.size() * 3, direct.byteSize()) << blob.size() << " of " << direct.byteSize() << " bytes";
    std::cout << "Position Servo result: " << direct.byteSize() << " bytes as float64, " << blob.size() << " stored\n";
    const auto decoded = decodeResult(blob);
    ASSERT_TRUE(decoded);
    expectSameTable(*decoded, direct);
}

TEST(ResultBlob, ChosenVariablesComeInTheirOrderAndOnlyThey)
{
    ServoRun run;
    const ResultTable direct = ResultTable::fromView(run.sim->results());
    const std::string blob = encodeResult(run.sim->results());
    const std::string a = direct.columns.at(5).name, b = direct.columns.at(1).name;
    const auto picked = decodeResult(blob, {a, "No#Such#Variable", b});
    ASSERT_TRUE(picked);
    ASSERT_EQ(picked->columns.size(), 2u);
    EXPECT_EQ(picked->columns[0].name, a);
    EXPECT_EQ(picked->columns[1].name, b);
    EXPECT_TRUE(bitwiseEqual(picked->columns[0].data, direct.column(a)->data));
    EXPECT_TRUE(bitwiseEqual(picked->time, direct.time));

    // Reading one variable does not touch the others: with the last column's bytes damaged,
    // `a` still reads, the whole result does not.
    std::string damaged = blob;
    damaged[damaged.size() - 3] ^= 0x55;
    EXPECT_TRUE(decodeResult(damaged, {a}));
    EXPECT_FALSE(decodeResult(damaged));
}

TEST(ResultBlob, ResultsStoredBeforeCompressionStillRead)
{
    ServoRun run;
    const ResultTable direct = ResultTable::fromView(run.sim->results());
    const auto old = decodeResult(direct.serialize());
    ASSERT_TRUE(old);
    expectSameTable(*old, direct);
    const auto picked = decodeResult(direct.serialize(), {direct.columns[2].name});
    ASSERT_TRUE(picked);
    ASSERT_EQ(picked->columns.size(), 1u);
    EXPECT_TRUE(bitwiseEqual(picked->columns[0].data, direct.columns[2].data));
}

TEST(ResultBlob, DamagedBlobsAreRefused)
{
    ServoRun run;
    const std::string blob = encodeResult(run.sim->results());
    EXPECT_FALSE(decodeResult(""));
    EXPECT_FALSE(decodeResult("TLRT"));
    EXPECT_FALSE(decodeResult(blob.substr(0, blob.size() - 1))) << "truncated";
    EXPECT_FALSE(decodeResult(blob + "x")) << "trailing bytes";
    std::string version = blob;
    version[4] = 9;
    EXPECT_FALSE(decodeResult(version)) << "unknown version";
    // The time column's sample count (after magic, version, column count, two empty-ish
    // strings: "" and "s") claims far more than its compressed bytes hold.
    std::string huge = blob;
    const std::size_t samplesAt = 4 + 4 + 4 + (4 + 0) + (4 + 1);
    const std::uint64_t claimed = std::uint64_t{1} << 40;
    std::memcpy(huge.data() + samplesAt, &claimed, sizeof claimed);
    EXPECT_FALSE(decodeResult(huge));
    std::string wrongCount = blob;
    const std::uint64_t fewer = 7;
    std::memcpy(wrongCount.data() + samplesAt, &fewer, sizeof fewer);
    EXPECT_FALSE(decodeResult(wrongCount)) << "the compressed column holds another count";
    std::string flipped = blob;
    flipped[flipped.size() - 3] ^= 0x55;
    EXPECT_FALSE(decodeResult(flipped)) << "corrupt compressed data";
}
