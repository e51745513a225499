#include "server/store/postgres/PostgresConnection.h"

namespace tlmhub::server {

PostgresConnection::PostgresConnection(const std::string& uri, std::uint64_t generation)
    : mConnection(uri), mGeneration(generation)
{
}

const char* PostgresConnection::prepared(const PgStatement& statement)
{
    // libpqxx sends the definition to the server on the statement's first execution (and
    // again by itself after it has reconnected).
    if (!mPrepared.contains(statement.name)) {
        mConnection.prepare(statement.name, statement.sql);
        mPrepared.insert(statement.name);
    }
    return statement.name;
}

namespace {

StoreErrc codeOfSqlState(const std::string& state)
{
    const std::string cls = state.substr(0, 2);
    if (cls == "23") return StoreErrc::Constraint;
    if (cls == "53") return StoreErrc::DiskFull;   // 53100 disk_full, and out of other resources
    if (state == "40001" || state == "40P01") return StoreErrc::Busy;
    if (state == "XX001" || state == "XX002") return StoreErrc::Corrupt;
    // Connection exceptions, and the server shutting down or not yet accepting connections.
    if (cls == "08" || state == "57P01" || state == "57P02" || state == "57P03") return StoreErrc::Unavailable;
    return StoreErrc::Internal;
}

} // namespace

StoreError toStoreError(const std::exception& e)
{
    const std::string what = std::string("PostgreSQL: ") + e.what();
    // A commit whose outcome is unknown lost its connection too.
    if (dynamic_cast<const pqxx::broken_connection*>(&e) || dynamic_cast<const pqxx::in_doubt_error*>(&e))
        return StoreError(StoreErrc::Unavailable, what);
    // libpqxx 6 throws these two (SQLSTATE 40001, 40P01) as transaction_rollback, not sql_error.
    if (dynamic_cast<const pqxx::serialization_failure*>(&e) || dynamic_cast<const pqxx::deadlock_detected*>(&e))
        return StoreError(StoreErrc::Busy, what);
    if (const auto* sql = dynamic_cast<const pqxx::sql_error*>(&e))
        return StoreError(codeOfSqlState(sql->sqlstate()), what);
    return StoreError(StoreErrc::Internal, what);
}

} // namespace tlmhub::server
