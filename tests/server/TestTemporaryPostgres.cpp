// The PostgreSQL test harness of issue 16: a real server started by the test, reached with
// libpqxx. Without postgresql-15 installed these tests fail (they are never skipped).
#include "TemporaryPostgres.h"

#include <gtest/gtest.h>
#include <pqxx/pqxx>

#include <chrono>
#include <filesystem>
#include <string>

namespace tlmhub::test {
namespace {

TEST(TemporaryPostgres, StoresUnicodeTextAndLargeBytea)
{
    const auto started = std::chrono::steady_clock::now();
    TemporaryPostgres pg;
    EXPECT_EQ(pg.uri(), "postgresql://tlmhub@127.0.0.1:" + std::to_string(pg.port()) + "/tlmhub_test");
    EXPECT_TRUE(std::filesystem::is_directory(pg.directory() / "data"));

    pqxx::connection conn(pg.uri() + "?connect_timeout=10");
    {
        pqxx::work txn(conn);
        txn.exec0("CREATE TABLE blobs (id integer PRIMARY KEY, name text NOT NULL, data bytea NOT NULL)");
        txn.commit();
    }
    const std::string name = "Druckbegrenzungsventil Δp ≤ 3 bar — 油圧 🚜";
    std::string data(2 * 1024 * 1024, '\0');
    for (std::size_t i = 0; i < data.size(); ++i) data[i] = static_cast<char>((i * 2654435761u) >> 13);
    {
        pqxx::work txn(conn);
        txn.exec_params0("INSERT INTO blobs (id, name, data) VALUES ($1, $2, $3)", 1, name,
                         pqxx::binarystring(data.data(), data.size()));
        txn.commit();
    }
    {
        pqxx::read_transaction txn(conn);
        const pqxx::row row = txn.exec1("SELECT name, data, octet_length(data), length(name) FROM blobs WHERE id = 1");
        EXPECT_EQ(row[0].as<std::string>(), name);
        const pqxx::binarystring back(row[1]);
        EXPECT_EQ(back.size(), data.size());
        EXPECT_TRUE(back.str() == data) << "bytea read back differs";
        EXPECT_EQ(row[2].as<long>(), 2 * 1024 * 1024);
        EXPECT_EQ(row[3].as<int>(), 40); // characters, not bytes: the database is UTF-8
        EXPECT_EQ(txn.exec1("SHOW server_encoding")[0].as<std::string>(), "UTF8");
    }
    EXPECT_LT(std::chrono::steady_clock::now() - started, std::chrono::seconds(60));
}

TEST(TemporaryPostgres, TwoServersRunSideBySideAndCleanUp)
{
    std::filesystem::path firstDir, secondDir;
    {
        TemporaryPostgres first;
        TemporaryPostgres second("other_db");
        firstDir = first.directory();
        secondDir = second.directory();
        EXPECT_NE(first.port(), second.port());
        EXPECT_NE(firstDir, secondDir);

        pqxx::connection a(first.uri() + "?connect_timeout=10");
        pqxx::connection b(second.uri() + "?connect_timeout=10");
        {
            pqxx::work txn(a);
            txn.exec0("CREATE TABLE only_in_first (x integer)");
            txn.commit();
        }
        pqxx::read_transaction txn(b);
        EXPECT_EQ(txn.exec1("SELECT current_database()")[0].as<std::string>(), "other_db");
        EXPECT_EQ(txn.exec1("SELECT count(*) FROM pg_tables WHERE tablename = 'only_in_first'")[0].as<int>(), 0);
        EXPECT_EQ(txn.exec1("SELECT inet_server_port()")[0].as<int>(), second.port());
    }
    // Stopped and removed on destruction.
    EXPECT_FALSE(std::filesystem::exists(firstDir));
    EXPECT_FALSE(std::filesystem::exists(secondDir));
}

TEST(TemporaryPostgres, RestartKeepsCommittedDataOnTheSamePort)
{
    TemporaryPostgres pg;
    const unsigned short port = pg.port();
    pqxx::connection before(pg.uri() + "?connect_timeout=10");
    {
        pqxx::work txn(before);
        txn.exec0("CREATE TABLE kept (x integer)");
        txn.exec0("INSERT INTO kept VALUES (42)");
        txn.commit();
    }
    pg.restart();
    EXPECT_EQ(pg.port(), port);
    // The old connection is gone; a new one on the same address sees the committed row.
    EXPECT_ANY_THROW(pqxx::nontransaction(before).exec("SELECT 1"));
    pqxx::connection after(pg.uri() + "?connect_timeout=10");
    pqxx::read_transaction txn(after);
    EXPECT_EQ(txn.exec1("SELECT x FROM kept")[0].as<int>(), 42);
}

} // namespace
} // namespace tlmhub::test
