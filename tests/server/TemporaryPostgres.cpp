#include "TemporaryPostgres.h"

#include "ChildProcess.h"

#include <pqxx/pqxx>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <grp.h>
#include <netinet/in.h>
#include <pwd.h>
#include <sstream>
#include <stdexcept>
#include <sys/socket.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

namespace tlmhub::test {
namespace {

using Clock = std::chrono::steady_clock;

// A loopback port nobody listens on right now (postgres binds it a moment later; a lost race
// shows up as "Address already in use" in the log and is retried with another port).
unsigned short freeLoopbackPort()
{
    const int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    if (fd < 0) throw std::runtime_error("TemporaryPostgres: socket failed");
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    addr.sin_port = 0;
    socklen_t len = sizeof addr;
    if (::bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0 ||
        ::getsockname(fd, reinterpret_cast<sockaddr*>(&addr), &len) != 0) {
        ::close(fd);
        throw std::runtime_error("TemporaryPostgres: cannot bind a loopback port");
    }
    ::close(fd);
    return ntohs(addr.sin_port);
}

std::string describeStatus(int status)
{
    if (WIFEXITED(status)) return "exited with status " + std::to_string(WEXITSTATUS(status));
    if (WIFSIGNALED(status)) return "killed by signal " + std::to_string(WTERMSIG(status));
    return "ended (wait status " + std::to_string(status) + ")";
}


// A cluster fresh from initdb, kept in the temporary directory for the clusters after it: initdb
// costs about a CPU-second, a copy (cp -a) a sixth of that, and a CI run makes some sixty
// clusters. Per user and PostgreSQL version; only for clusters that need not be durable (a
// copy is not synced to disk).
std::filesystem::path clusterTemplate()
{
    const std::string version = std::filesystem::path(TemporaryPostgres::kBinDir).parent_path().filename().string();
    return std::filesystem::temp_directory_path() /
           ("tlmhub-pg-template-" + version + "-" + std::to_string(::geteuid()));
}

// Copies `from` to `to` as `who` (so the copy is the cluster user's); true when cp succeeded.
bool copyCluster(const std::filesystem::path& from, const std::filesystem::path& to,
                 const std::filesystem::path& dir, const RunAs& who)
{
    const int cp = spawn({"/bin/cp", "-a", from.string(), to.string()}, dir / "copy.log", dir, who);
    const int status = waitUntil(cp, Clock::now() + std::chrono::seconds(60));
    if (status == -1) {
        ::kill(cp, SIGKILL);
        ::waitpid(cp, nullptr, 0);
        return false;
    }
    return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

// Makes the cluster just made by initdb at `data` the template, unless another test process
// did first: a whole copy appears at once (rename), never a partial one. Failing here costs
// only the next cluster an initdb.
void publishClusterTemplate(const std::filesystem::path& data, const std::filesystem::path& dir, const RunAs& who)
{
    const std::filesystem::path target = clusterTemplate();
    std::error_code ignored;
    if (std::filesystem::exists(target / "PG_VERSION", ignored)) return;
    const std::filesystem::path staging = target.string() + "." + std::to_string(::getpid()) + "." + dir.filename().string();
    if (copyCluster(data, staging, dir, who) && ::rename(staging.c_str(), target.c_str()) == 0) return;
    std::filesystem::remove_all(staging, ignored);
}

} // namespace

TemporaryPostgres::TemporaryPostgres(std::string dbName, bool durable) : mDbName(std::move(dbName)), mDurable(durable)
{
    const std::filesystem::path bin = kBinDir;
    for (const char* tool : {"initdb", "postgres"}) {
        if (::access((bin / tool).c_str(), X_OK) != 0)
            throw std::runtime_error(std::string("TemporaryPostgres: ") + (bin / tool).string() +
                                     " not found or not executable: install Debian's postgresql-15 "
                                     "(apt-get install postgresql-15, or scripts/install-deps.sh)");
    }
    const RunAs who = runAsNobodyIfRoot();

    std::string tmpl = (std::filesystem::temp_directory_path() / "tlmhub-pg-XXXXXX").string();
    if (::mkdtemp(tmpl.data()) == nullptr)
        throw std::runtime_error("TemporaryPostgres: mkdtemp failed for " + tmpl + ": " + std::strerror(errno));
    mDir = tmpl;
    try {
        const auto data = mDir / "data";
        const auto socketDir = mDir / "socket";
        std::filesystem::create_directory(socketDir);
        if (who.drop) {
            // The parent of mDir (normally /tmp) must be searchable by nobody.
            if (::chown(mDir.c_str(), who.uid, who.gid) != 0 || ::chown(socketDir.c_str(), who.uid, who.gid) != 0)
                throw std::runtime_error("TemporaryPostgres: cannot chown " + mDir.string() + " to nobody");
        }

        bool copied = false;
        std::error_code ignored;
        if (!durable && std::filesystem::exists(clusterTemplate() / "PG_VERSION", ignored)) {
            copied = copyCluster(clusterTemplate(), data, mDir, who);
            if (!copied) std::filesystem::remove_all(data, ignored); // initdb wants an empty directory
        }
        if (!copied) {
            // initdb: trust authentication (the server listens on loopback only, in a directory
            // only its user can enter).
            const auto initdbLog = mDir / "initdb.log";
            std::vector<std::string> initdbArgs{(bin / "initdb").string(), "-D", data.string(), "-U", kUser,
                                                "--auth=trust", "--encoding=UTF8", "--locale=C.UTF-8", "--no-instructions"};
            if (!durable) initdbArgs.push_back("--no-sync");
            const int initdb = spawn(initdbArgs, initdbLog, mDir, who);
            const int initStatus = waitUntil(initdb, Clock::now() + std::chrono::seconds(60));
            if (initStatus == -1) {
                ::kill(initdb, SIGKILL);
                ::waitpid(initdb, nullptr, 0);
                throw std::runtime_error("TemporaryPostgres: initdb did not finish within 60 s; log:\n" + tailOf(initdbLog, 4000));
            }
            if (!WIFEXITED(initStatus) || WEXITSTATUS(initStatus) != 0)
                throw std::runtime_error("TemporaryPostgres: initdb " + describeStatus(initStatus) + "; log:\n" +
                                         tailOf(initdbLog, 4000));
            if (!durable) publishClusterTemplate(data, mDir, who);
        }

        // postgres, retried on another port if the one picked was taken in the meantime.
        start(0);

        pqxx::connection admin(uri("postgres") + "?connect_timeout=10");
        pqxx::nontransaction txn(admin);
        txn.exec0("CREATE DATABASE " + txn.quote_name(mDbName));
    } catch (...) {
        stop();
        std::error_code ignored;
        std::filesystem::remove_all(mDir, ignored);
        throw;
    }
}

void TemporaryPostgres::start(unsigned short port)
{
    const std::filesystem::path bin = kBinDir;
    const RunAs who = runAsNobodyIfRoot();
    const auto data = mDir / "data";
    const auto socketDir = mDir / "socket";
    const auto deadline = Clock::now() + std::chrono::seconds(30);
    for (int attempt = 1;; ++attempt) {
        mPort = port != 0 ? port : freeLoopbackPort();
        // max_connections: PostgreSQL's default, room for a cluster of 5 nodes (each up to 8
        // pooled connections and a LISTEN one) and the test's own.
        std::vector<std::string> args{(bin / "postgres").string(), "-D", data.string(), "-h", "127.0.0.1",
                                      "-p", std::to_string(mPort), "-k", socketDir.string(), "-c",
                                      "max_connections=100"};
        if (!mDurable)
            for (const char* setting : {"fsync=off", "synchronous_commit=off", "full_page_writes=off"})
                args.insert(args.end(), {"-c", setting});
        mPid = spawn(args, mDir / "postgres.log", mDir, who);
        bool ready = false;
        std::string lastError = "no connection attempt yet";
        while (!ready) {
            const int status = waitUntil(mPid, Clock::now());
            if (status != -1) {
                mPid = -1;
                const std::string log = logTail(4000);
                // A port of our choosing may be taken in the meantime; a given one must be
                // retried (a restart: the old server's socket may linger a moment).
                if (attempt < 3 && log.find("Address already in use") != std::string::npos) {
                    if (port != 0) std::this_thread::sleep_for(std::chrono::milliseconds(500));
                    break;
                }
                throw std::runtime_error("TemporaryPostgres: postgres " + describeStatus(status) +
                                         " before accepting connections on 127.0.0.1:" +
                                         std::to_string(mPort) + "; log:\n" + log);
            }
            if (Clock::now() >= deadline)
                throw std::runtime_error("TemporaryPostgres: postgres did not accept connections on 127.0.0.1:" +
                                         std::to_string(mPort) + " within 30 s (last error: " + lastError +
                                         "); log:\n" + logTail(4000));
            try {
                pqxx::connection probe(uri("postgres") + "?connect_timeout=2");
                ready = true;
            } catch (const std::exception& e) {
                lastError = e.what();
                std::this_thread::sleep_for(std::chrono::milliseconds(100));
            }
        }
        if (ready) return;
    }
}

void TemporaryPostgres::restart()
{
    stop();
    start(mPort);
}

TemporaryPostgres::~TemporaryPostgres()
{
    stop();
    std::error_code ignored;
    std::filesystem::remove_all(mDir, ignored);
}

void TemporaryPostgres::stop()
{
    if (mPid <= 0) return;
    // SIGINT is PostgreSQL's fast shutdown: sessions are disconnected, no waiting for clients.
    ::kill(mPid, SIGINT);
    if (waitUntil(mPid, Clock::now() + std::chrono::seconds(30)) == -1) {
        ::kill(mPid, SIGQUIT); // immediate shutdown
        if (waitUntil(mPid, Clock::now() + std::chrono::seconds(5)) == -1) {
            ::kill(-mPid, SIGKILL); // the whole process group: postmaster and backends
            ::waitpid(mPid, nullptr, 0);
        }
    }
    mPid = -1;
}

std::string TemporaryPostgres::uri() const { return uri(mDbName); }

std::string TemporaryPostgres::uri(const std::string& dbName) const
{
    return std::string("postgresql://") + kUser + "@127.0.0.1:" + std::to_string(mPort) + "/" + dbName;
}

std::string TemporaryPostgres::logTail(std::size_t maxBytes) const
{
    return tailOf(mDir / "postgres.log", maxBytes);
}

} // namespace tlmhub::test
