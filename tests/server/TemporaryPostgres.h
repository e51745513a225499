#pragma once
// Test support for issue 16: a real PostgreSQL server the test starts itself, from Debian's
// postgresql-15 (/usr/lib/postgresql/15/bin), in a fresh temporary directory, listening on a
// free loopback TCP port (its Unix socket inside that directory, not /var/run/postgresql).
// Missing binaries throw (the test fails, naming the package to install); nothing is skipped.
#include <filesystem>
#include <string>

namespace tlmhub::test {

class TemporaryPostgres {
public:
    // Runs initdb, starts postgres, waits (at most 30 s) until it accepts connections and
    // creates the database `dbName`. Throws std::runtime_error naming the step that failed,
    // with the tail of that step's log. Tests throw their data away, so by default nothing is
    // flushed to disk; `durable` keeps PostgreSQL's defaults (fsync and synchronous commit
    // on), for benchmarks of what a real server costs.
    explicit TemporaryPostgres(std::string dbName = "tlmhub_test", bool durable = false);
    // Fast shutdown (SIGINT; SIGQUIT then SIGKILL if it has not ended after 30 s), then the
    // temporary directory is removed.
    ~TemporaryPostgres();
    TemporaryPostgres(const TemporaryPostgres&) = delete;
    TemporaryPostgres& operator=(const TemporaryPostgres&) = delete;

    // postgresql://tlmhub@127.0.0.1:PORT/DBNAME (trust authentication on loopback only).
    std::string uri() const;
    // The same for another database of this server (e.g. "postgres").
    std::string uri(const std::string& dbName) const;
    unsigned short port() const { return mPort; }
    const std::filesystem::path& directory() const { return mDir; }
    // Fast shutdown, then postgres again on the same data directory and port (every
    // connection is lost; what was committed is kept). Throws as the constructor does.
    void restart();
    // The last `maxBytes` of the server's log (stdout and stderr of postgres).
    std::string logTail(std::size_t maxBytes = 4000) const;

    static constexpr const char* kBinDir = "/usr/lib/postgresql/15/bin";
    static constexpr const char* kUser = "tlmhub";

private:
    // Starts postgres on `port` (0: a free one, retried if taken meanwhile) and waits until it
    // accepts connections.
    void start(unsigned short port);
    void stop();

    std::filesystem::path mDir;
    std::string mDbName;
    unsigned short mPort = 0;
    int mPid = -1;
    bool mDurable = false;
};

} // namespace tlmhub::test
