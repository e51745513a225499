#include "server/store/Database.h"
#include "server/protocol/EmbeddedProtocol.h"

#include <gtest/gtest.h>

#include <filesystem>

using namespace tlmhub::server;

TEST(Database, OpensFileInWalMode)
{
    const auto dir = std::filesystem::temp_directory_path() / "tlmhub-db-test";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    Database db((dir / "t.sqlite").string());
    SQLite::Statement q(db.sql(), "PRAGMA journal_mode");
    ASSERT_TRUE(q.executeStep());
    EXPECT_EQ(q.getColumn(0).getString(), "wal");
    std::filesystem::remove_all(dir);
}

TEST(EmbeddedProtocol, HoldsEveryProtocolFile)
{
    std::size_t onDisk = 0;
    for (const auto& e : std::filesystem::directory_iterator(TLMHUB_SOURCE_DIR "/protocol"))
        if (e.path().extension() == ".json") ++onDisk;
    EXPECT_EQ(embeddedProtocolFiles().size(), onDisk);
    EXPECT_GT(onDisk, 0u);
}
