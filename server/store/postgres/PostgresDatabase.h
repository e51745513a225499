#pragma once
// The PostgreSQL back end's access to its server: a small pool of connections, each store call
// run on one of them with libpqxx's exceptions turned into StoreError.
//
// When a connection turns out broken (the server restarted, or an administrator ended the
// session), every connection opened before that is distrusted: each is closed instead of
// being used again, so the next calls get fresh connections rather than finding the dead ones
// one by one.
#include "server/store/ConnectionPool.h"
#include "server/store/postgres/PostgresConnection.h"

#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <string>
#include <thread>

namespace tlmhub::server {

// Whether a call may simply run again when its connection broke midway: true for reads and
// for single statements whose second run changes nothing the first did not. Other writes
// might have been committed before the connection went, so they fail (Unavailable) instead,
// unless the connection was found dead before they sent anything.
enum class Idempotent { No, Yes };

class PostgresDatabase {
public:
    // Connects lazily; `uri` gets connect_timeout=10 unless it sets one, so an unreachable
    // server fails a call within seconds instead of the operating system's minutes.
    PostgresDatabase(const std::string& uri, unsigned maxConnections);

    // "user@host:port/db", no password.
    const std::string& endpoint() const { return mEndpoint; }
    // The URI connections are opened with (for a connection of a store's own, e.g. LISTEN).
    const std::string& uri() const { return mUri; }

    // Runs `work(PostgresConnection&)` on a leased connection. A transaction `work` opens is
    // rolled back by its destructor when `work` throws; serialization failures and deadlocks
    // (the transaction rolled back whole) run it again a few times before giving up with Busy.
    // A connection found broken is closed; `work` then runs once more on a fresh one if it is
    // idempotent or had not sent a statement yet, else fails with Unavailable.
    template <typename Work>
    auto run(Idempotent idempotent, Work&& work) -> decltype(work(std::declval<PostgresConnection&>()))
    {
        bool reconnected = false;
        for (int attempt = 1;; ++attempt) {
            auto lease = acquire();
            lease->forgetSentStatements();
            try {
                return work(*lease);
            } catch (const pqxx::serialization_failure& e) {
                if (attempt >= kMaxAttempts) throw toStoreError(e);
                backOff(attempt);
            } catch (const pqxx::deadlock_detected& e) {
                if (attempt >= kMaxAttempts) throw toStoreError(e);
                backOff(attempt);
            } catch (const pqxx::pqxx_exception& e) {
                const bool broken = dynamic_cast<const pqxx::broken_connection*>(&e) || !lease->isOpen();
                if (!broken) throw toStoreError(e.base());
                lease.discard();
                distrustOpenConnections();
                // A commit whose outcome is unknown (in_doubt_error) is never run again.
                const bool harmless = idempotent == Idempotent::Yes || !lease->sentStatement();
                const bool again = harmless && !reconnected && !dynamic_cast<const pqxx::in_doubt_error*>(&e);
                if (!again)
                    throw StoreError(StoreErrc::Unavailable,
                                     "lost the connection to PostgreSQL " + mEndpoint + ": " + e.base().what());
                reconnected = true;
            }
        }
    }

    static constexpr unsigned kMaxConnections = 8;
    static constexpr int kMaxAttempts = 4;

private:
    // An open connection that was opened after the last broken one; throws StoreError(Unavailable)
    // naming the server when none can be opened.
    ConnectionPool<PostgresConnection>::Lease acquire();
    void distrustOpenConnections() { ++mGeneration; }
    static void backOff(int attempt) { std::this_thread::sleep_for(std::chrono::milliseconds(5 * attempt)); }

    std::string mUri;
    std::string mEndpoint;
    // Bumped whenever a connection is found broken; a connection remembers the value it was
    // opened at and is trusted only while that is still current.
    std::atomic<std::uint64_t> mGeneration{0};
    ConnectionPool<PostgresConnection> mPool;
};

// "user@host:port/db" for a postgresql:// URI (defaults filled in, the password left out).
std::string postgresEndpoint(const std::string& uri);

} // namespace tlmhub::server
