#include "server/store/postgres/PostgresDatabase.h"

#include <algorithm>

namespace tlmhub::server {

namespace {

std::string withConnectTimeout(const std::string& uri)
{
    if (uri.find("connect_timeout=") != std::string::npos) return uri;
    return uri + (uri.find('?') == std::string::npos ? "?" : "&") + "connect_timeout=10";
}

} // namespace

std::string postgresEndpoint(const std::string& uri)
{
    // postgresql://[user[:password]@][host][:port][/dbname][?parameters]
    std::string rest = uri.substr(uri.find("://") == std::string::npos ? 0 : uri.find("://") + 3);
    rest = rest.substr(0, rest.find('?'));
    const auto slash = rest.find('/');
    const std::string authority = rest.substr(0, slash);
    std::string db = slash == std::string::npos ? "" : rest.substr(slash + 1);
    const auto at = authority.rfind('@');
    std::string user = at == std::string::npos ? "" : authority.substr(0, at);
    user = user.substr(0, user.find(':'));   // never the password
    std::string hostPort = at == std::string::npos ? authority : authority.substr(at + 1);
    // The port follows the last ':' unless that is inside an [IPv6] address.
    const auto colon = hostPort.rfind(':');
    const bool hasPort = colon != std::string::npos && hostPort.find(']', colon) == std::string::npos;
    std::string host = hasPort ? hostPort.substr(0, colon) : hostPort;
    const std::string port = hasPort ? hostPort.substr(colon + 1) : "5432";
    if (host.empty()) host = "localhost";
    if (db.empty()) db = user;   // libpq's default database is the user's name
    return (user.empty() ? "" : user + "@") + host + ":" + port + "/" + db;
}

PostgresDatabase::PostgresDatabase(const std::string& uri, unsigned maxConnections)
    : mUri(withConnectTimeout(uri)),
      mEndpoint(postgresEndpoint(uri)),
      mPool([this] { return std::make_unique<PostgresConnection>(mUri, mGeneration.load()); },
            std::clamp(maxConnections, 1u, kMaxConnections))
{
}

ConnectionPool<PostgresConnection>::Lease PostgresDatabase::acquire()
{
    for (;;) {
        try {
            auto lease = mPool.acquire();
            if (lease->generation() == mGeneration.load() && lease->isOpen()) return lease;
            // Opened before a connection broke (likely broken too), or known closed already.
            lease.discard();
        } catch (const pqxx::pqxx_exception& e) {
            throw StoreError(StoreErrc::Unavailable,
                             "cannot connect to PostgreSQL " + mEndpoint + ": " + e.base().what());
        }
    }
}

} // namespace tlmhub::server
