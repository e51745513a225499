#pragma once
// One connection to the PostgreSQL server, used by one thread at a time (leased from the
// pool). Every SQL text a store runs is a PgStatement: prepared on this connection the first
// time it is used and run by name from then on, so the server parses and plans it once per
// connection.
#include "server/store/StoreError.h"

#include <pqxx/pqxx>

#include <cstdint>
#include <exception>
#include <optional>
#include <string>
#include <unordered_set>
#include <utility>

namespace tlmhub::server {

// A statement of a store: a name unique among all stores (the prepared statement's name on
// the server) and its SQL text with $1, $2, ... parameters.
struct PgStatement {
    const char* name;
    const char* sql;
};

// The database's clock in milliseconds, for SQL text: every node of a deployment reads the same one.
#define TLMHUB_NOW_MS "(extract(epoch from clock_timestamp()) * 1000)::bigint"

class PostgresConnection {
public:
    // Connects to `uri` (a libpq connection URI); throws pqxx::broken_connection.
    // `generation`: PostgresDatabase's count of broken connections when this one was opened.
    PostgresConnection(const std::string& uri, std::uint64_t generation);

    pqxx::connection& raw() { return mConnection; }
    bool isOpen() const { return mConnection.is_open(); }
    std::uint64_t generation() const { return mGeneration; }

    // Runs `statement` in `tx` (a transaction on this connection), preparing it first if this
    // connection has not yet.
    template <typename... Args>
    pqxx::result exec(pqxx::transaction_base& tx, const PgStatement& statement, Args&&... args)
    {
        mSentStatement = true;
        return tx.exec_prepared(prepared(statement), std::forward<Args>(args)...);
    }

    // Whether exec() has sent a statement since forgetSentStatements(): a call that failed
    // before it did (e.g. opening its transaction on a dead connection) changed nothing.
    bool sentStatement() const { return mSentStatement; }
    void forgetSentStatements() { mSentStatement = false; }

private:
    const char* prepared(const PgStatement& statement);

    pqxx::connection mConnection;
    std::uint64_t mGeneration;
    bool mSentStatement = false;
    std::unordered_set<std::string> mPrepared;
};

// The StoreError for a failure libpqxx reported: a lost connection is Unavailable; a failed
// statement is mapped by its SQLSTATE (class 23 Constraint, class 53 DiskFull, 40001 and 40P01
// Busy, XX001/XX002 Corrupt, anything else Internal).
StoreError toStoreError(const std::exception& e);

// A column that may be NULL.
template <typename T>
std::optional<T> nullable(const pqxx::field& field)
{
    if (field.is_null()) return std::nullopt;
    return field.as<T>();
}

// The NULL parameter for an absent value (libpqxx 6 passes a null `const char*` as NULL).
inline const char* orNull(const std::optional<std::string>& value)
{
    return value ? value->c_str() : nullptr;
}

} // namespace tlmhub::server
