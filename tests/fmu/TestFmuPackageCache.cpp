// Issue 37 M4: every FMIWrapper unpacked and parsed its FMU at every load and compile (10-25
// ms each): four uploads of 1000-wrapper models stalled the server. A package no model holds
// now stays unpacked within a byte bound, and a file is hashed again only when it changed.
#include "FmuImportTestSupport.h"

#include "fmu/FmuPackage.h"

#include <gtest/gtest.h>

#include <chrono>

namespace tlmhub::fmu::test {
namespace {

// Restores the default bound however a test ends.
struct CacheBytes {
    explicit CacheBytes(std::uintmax_t bytes) { FmuPackage::setCacheBytes(bytes); }
    ~CacheBytes() { FmuPackage::setCacheBytes(FmuPackage::kDefaultCacheBytes); }
};

std::shared_ptr<const FmuPackage> opened(const fs::path& file)
{
    auto package = FmuPackage::open(file);
    EXPECT_TRUE(package) << package.status().message();
    return package ? *package : nullptr;
}

TEST(FmuPackageCache, AnFmuNoModelHoldsStaysUnpackedWithinTheCacheBytes)
{
    TemporaryDirectory dir;
    const fs::path file = dir.path() / "integrator.fmu";
    writeIntegratorFmu(file);
    CacheBytes bound(FmuPackage::kDefaultCacheBytes);
    std::shared_ptr<const FmuPackage> held = opened(file);
    ASSERT_TRUE(held);
    const fs::path unpacked = held->directory();
    EXPECT_GT(held->unpackedBytes(), 0u);
    held.reset();   // no model holds it now
    ASSERT_TRUE(fs::exists(unpacked)) << "kept for the next load";
    held = opened(file);
    ASSERT_TRUE(held);
    EXPECT_EQ(held->directory(), unpacked) << "the same package, not unpacked again";

    // With no room, a package lives only while a model holds it.
    FmuPackage::setCacheBytes(0);
    EXPECT_TRUE(fs::exists(unpacked)) << "still held";
    held.reset();
    EXPECT_FALSE(fs::exists(unpacked));
    held = opened(file);
    ASSERT_TRUE(held);
    EXPECT_NE(held->directory(), unpacked);
}

TEST(FmuPackageCache, AChangedFileIsReadAgain)
{
    TemporaryDirectory dir;
    const fs::path file = dir.path() / "integrator.fmu";
    writeIntegratorFmu(file);
    auto before = FmuPackage::open(file);
    ASSERT_TRUE(before);
    const std::string guid = (*before)->description().guid;
    std::string description = integratorDescription();
    const auto at = description.find(guid);
    ASSERT_NE(at, std::string::npos);
    description.replace(at, guid.size(), "{00000000-0000-0000-0000-000000000037}");
    writeIntegratorFmu(file, description);
    fs::last_write_time(file, fs::last_write_time(file) + std::chrono::seconds(2));
    auto after = FmuPackage::open(file);
    ASSERT_TRUE(after) << after.status().message();
    EXPECT_EQ((*after)->description().guid, "{00000000-0000-0000-0000-000000000037}");
    EXPECT_NE((*after)->directory(), (*before)->directory());
}

} // namespace
} // namespace tlmhub::fmu::test
