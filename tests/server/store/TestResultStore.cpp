// ResultStore's contract (server/store/ResultStore.h) on both back ends: blobs come back byte
// for byte, results decode, the quota figure counts one owner's results only.
#include "StoreBackends.h"

#include "core/ComponentFactory.h"
#include "core/ResultTable.h"
#include "core/Simulation.h"
#include "server/store/ResultBlob.h"
#include "server/store/StoreError.h"

#include <cstring>
#include <stdexcept>

using namespace tlmhub::server;

namespace tlmhub::test {
namespace {

class ResultStoreConformance : public StoreTest {};
TLMHUB_STORE_CONFORMANCE(ResultStoreConformance);

// A result of 20 columns of 100k samples: sine waves of different frequencies. Run once per
// process, kept for both back ends.
struct LargeRun {
    LargeRun()
    {
        for (int i = 0; i < 20; ++i) {
            auto sine = ComponentFactory::instance().create("SignalSineWave");
            if (!sine) throw std::runtime_error("no component type SignalSineWave");
            sine->setNameRaw("Sine" + std::to_string(i));
            Parameter* frequency = sine->parameters().find("f#Value");
            if (!frequency) throw std::runtime_error("SignalSineWave has no parameter f#Value");
            frequency->value = std::to_string(0.5 + 0.25 * i);
            root.addComponent(std::move(sine));
        }
        Result<Simulation> compiled = compile(root, {.startTime = 0.0, .stopTime = 10.0, .timestep = 1e-4, .logSamples = 100'000});
        if (!compiled) throw std::runtime_error(describe(compiled.status()));
        sim.emplace(std::move(*compiled));
        if (!sim->run()) throw std::runtime_error("the sine waves did not run");
        table = ResultTable::fromView(sim->results());
        blob = encodeResult(sim->results());
    }
    System root;
    std::optional<Simulation> sim;
    ResultTable table;
    std::string blob;
};

const LargeRun& largeRun()
{
    static const LargeRun run;
    return run;
}

bool sameBits(const std::vector<double>& a, const std::vector<double>& b)
{
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

TEST_P(ResultStoreConformance, BlobComesBackByteForByteWithEveryByteValue)
{
    std::string blob;
    for (int round = 0; round < 4; ++round)
        for (int b = 0; b < 256; ++b) blob.push_back(static_cast<char>(b));
    blob += std::string(3, '\0') + "\\x00'\"" + std::string(1, '\xff');
    const std::int64_t id = addFinishedJob(1, &blob);
    const auto back = store().results().blob(id);
    ASSERT_TRUE(back);
    EXPECT_EQ(back->size(), blob.size());
    EXPECT_TRUE(*back == blob);
}

TEST_P(ResultStoreConformance, EmptyBlobIsAResult)
{
    const std::string empty;
    const std::int64_t id = addFinishedJob(1, &empty);
    EXPECT_TRUE(store().results().has(id));
    EXPECT_EQ(store().results().blob(id), "");
}

TEST_P(ResultStoreConformance, JobsWithoutAResultHaveNone)
{
    const std::int64_t finished = addFinishedJob(1, nullptr), queued = addJob(1);
    for (std::int64_t id : {finished, queued, std::int64_t{1000}}) {
        EXPECT_FALSE(store().results().has(id)) << id;
        EXPECT_FALSE(store().results().blob(id)) << id;
        EXPECT_FALSE(store().results().result(id)) << id;
    }
}

TEST_P(ResultStoreConformance, LargeResultRoundTripsAndDecodesOnlyTheChosenVariables)
{
    const LargeRun& run = largeRun();
    ASSERT_EQ(run.table.columns.size(), 20u);
    ASSERT_EQ(run.table.time.size(), 100'000u);
    const std::int64_t id = addFinishedJob(1, &run.blob);
    const auto blob = store().results().blob(id);
    ASSERT_TRUE(blob);
    EXPECT_EQ(blob->size(), run.blob.size());
    EXPECT_TRUE(*blob == run.blob);
    EXPECT_EQ(store().results().storedBytes(1), run.blob.size());

    const auto all = store().results().result(id);
    ASSERT_TRUE(all);
    EXPECT_TRUE(sameBits(all->time, run.table.time));
    ASSERT_EQ(all->columns.size(), run.table.columns.size());
    for (std::size_t i = 0; i < all->columns.size(); ++i) {
        EXPECT_EQ(all->columns[i].name, run.table.columns[i].name);
        EXPECT_TRUE(sameBits(all->columns[i].data, run.table.columns[i].data)) << run.table.columns[i].name;
    }

    const std::string a = run.table.columns[17].name, b = run.table.columns[3].name;
    const auto picked = store().results().result(id, {a, "No#Such#Variable", b});
    ASSERT_TRUE(picked);
    ASSERT_EQ(picked->columns.size(), 2u);
    EXPECT_EQ(picked->columns[0].name, a);
    EXPECT_EQ(picked->columns[1].name, b);
    EXPECT_TRUE(sameBits(picked->columns[0].data, run.table.columns[17].data));
    EXPECT_TRUE(sameBits(picked->columns[1].data, run.table.columns[3].data));
}

TEST_P(ResultStoreConformance, AStoredBlobThatIsNotAResultIsCorrupt)
{
    const std::string garbage = "not a result";
    const std::int64_t id = addFinishedJob(1, &garbage);
    try {
        store().results().result(id);
        ADD_FAILURE() << "no StoreError";
    } catch (const StoreError& e) {
        EXPECT_EQ(e.code(), StoreErrc::Corrupt);
    }
}

TEST_P(ResultStoreConformance, StoredBytesSumsTheResultsOfThatOwnersJobsOnly)
{
    const std::string small(10, 's'), large(2000, 'l'), other(333, 'o');
    EXPECT_EQ(store().results().storedBytes(1), 0u);
    addFinishedJob(1, &small);
    const std::int64_t big = addFinishedJob(1, &large);
    addFinishedJob(1, nullptr);
    addJob(1);
    addFinishedJob(2, &other);
    EXPECT_EQ(store().results().storedBytes(1), 2010u);
    EXPECT_EQ(store().results().storedBytes(2), 333u);
    EXPECT_EQ(store().results().storedBytes(3), 0u);
    ASSERT_TRUE(store().jobs().remove(big));
    EXPECT_EQ(store().results().storedBytes(1), 10u);
}

} // namespace
} // namespace tlmhub::test
