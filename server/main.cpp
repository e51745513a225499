// tlmhub-server: the simulation service. Parses the start-up options, opens the data
// directory, seeds the examples, then serves HTTP and WebSocket until SIGTERM or SIGINT.
// With --backup or --restore it does only that to the database and exits.
#include "server/app/ServerOptions.h"
#include "server/app/ShutdownSignals.h"
#include "server/app/TlmhubApp.h"
#include "server/http/Listener.h"
#include "server/protocol/SchemaValidator.h"
#include "server/store/sqlite/SqliteStorage.h"

#include "core/ComponentLibrary.h"
#include "core/FileAccess.h"
#include "fmu/FmuLoadPolicy.h"
#include "fmu/FmuPackage.h"

#include <boost/asio/executor_work_guard.hpp>
#include <boost/asio/io_context.hpp>

#include <chrono>
#include <filesystem>
#include <iostream>
#include <thread>

using namespace tlmhub::server;
namespace net = boost::asio;
namespace fs = std::filesystem;

namespace {

// How long the orderly stop may take after SIGTERM or SIGINT (the bound is 5 s).
constexpr std::chrono::milliseconds kShutdownGrace{4000};

// --backup FILE or --restore FILE (docs/storage.md); returns the exit status.
int backupOrRestore(const ServerOptions& options)
{
    if (isPostgresUri(options.database)) {
        std::cerr << "tlmhub-server: a PostgreSQL database is backed up with pg_dump and restored with "
                     "pg_restore (see docs/storage.md)\n";
        return 2;
    }
    StorageConfig config = storageConfig(options);
    const fs::path database = config.database;
    try {
        if (!options.backupFile.empty()) {
            // Opening would make an empty database where there is none.
            if (!fs::exists(database))
                throw StoreError(StoreErrc::Unavailable, "there is no database " + database.string() + " (see --data-dir)");
            // One connection, and no disk reserve: a server may be using the database meanwhile.
            config.maxConnections = 1;
            config.reserveBytes = 0;
            const auto storage = openStorage(config);
            storage->backup(options.backupFile);
            std::cout << "backup of " << storage->describe() << " written to " << options.backupFile << " ("
                      << fs::file_size(options.backupFile) << " bytes, schema version " << storage->schemaVersion()
                      << ")\n";
        } else {
            fs::create_directories(options.dataDir);
            const bool replacing = fs::exists(database);
            restoreSqliteBackup(options.restoreFile, database);
            std::cout << "restored " << options.restoreFile << " into " << database.string();
            if (replacing) std::cout << "; the previous database is kept as " << database.string() << ".before-restore";
            std::cout << "\n";
        }
    } catch (const std::exception& e) {
        std::cerr << "tlmhub-server: " << e.what() << "\n";
        return 1;
    }
    return 0;
}

} // namespace

int main(int argc, char** argv)
{
    ServerOptions options;
    std::string error, help;
    if (!parseServerOptions(argc, argv, options, error, help)) {
        std::cerr << "tlmhub-server: " << error << "\n";
        return 2;
    }
    if (!help.empty()) {
        std::cout << help;
        return 0;
    }
    if (!options.backupFile.empty() || !options.restoreFile.empty()) return backupOrRestore(options);
    ShutdownSignals shutdownSignals(kShutdownGrace);
    // Models come from users: they must not read or write the host's files.
    tlmhub::setModelFileAccess(false);
    // Component libraries run code with the server's rights: only this start-up flag,
    // given by whoever starts the server, loads them.
    for (const std::string& lib : options.componentLibs) {
        const tlmhub::Result<std::vector<std::string>> added = tlmhub::loadComponentLibrary(lib);
        if (!added) {
            std::cerr << "tlmhub-server: " << tlmhub::describe(added.status()) << "\n";
            return 1;
        }
        std::cout << "loaded " << added->size() << " component types from " << lib << "\n";
    }
    // An FMU is native code too: models import them only from the administrator's directory.
    if (!options.fmuDir.empty()) {
        const tlmhub::Result<tlmhub::fmu::FmuLoadPolicy> policy = tlmhub::fmu::FmuLoadPolicy::onlyUnder(options.fmuDir);
        if (!policy) {
            std::cerr << "tlmhub-server: " << tlmhub::describe(policy.status()) << "\n";
            return 1;
        }
        tlmhub::fmu::setFmuLoadPolicy(*policy);
        tlmhub::fmu::FmuPackage::setCacheBytes(options.fmuCacheBytes);
        std::cout << "FMUs load from " << policy->directory.string() << "\n";
    }
    setPasswordCost(options.passwordCost);
    tlmhub::ParameterEvaluator::setDefaultBudget(options.maxParameterEvaluations);
    if (options.passwordCost == PasswordCost::Minimal)
        std::cout << "WARNING: --password-hash-cost minimal: new password hashes are cheap to guess (test servers only)\n";
    try {
        // A broken embedded schema shows now, not on the first request.
        SchemaValidator::protocol();
        TlmhubApp app(options);
        std::cout << "storage: " << app.storage().describe() << ", schema version "
                  << app.storage().schemaVersion() << "\n";
        std::string seedLog;
        if (const auto generated = app.bootstrap(seedLog))
            std::cout << "created user 'admin' with password: " << *generated
                      << "\n(shown once; set TLMHUB_ADMIN_PASSWORD on first start to choose it)\n";
        if (!seedLog.empty()) std::cout << seedLog;
        std::cout << "node " << app.queueNode().id << ", role " << options.role << "\n";

        net::io_context ioc;
        const auto address = net::ip::make_address(options.host);
        auto listener = std::make_shared<Listener>(ioc, net::ip::tcp::endpoint(address, options.port), app,
                                                   TransportLimits{options.maxBodyBytes, options.wsQueueLimit, options.wsQueueBytes});
        listener->run();
        app.startJobs();

        // The I/O threads return from run() only at ioc.stop(), the last step of the orderly
        // stop: not as soon as the listener is closed while the stop is still under way.
        const auto keepRunning = net::make_work_guard(ioc);
        shutdownSignals.onSignal([&] {
            listener->stop();
            app.shutdown();   // running jobs stop (interrupted, or back in the queue) before we exit
            ioc.stop();
        });

        const auto endpoint = listener->localEndpoint();
        std::cout << "tlmhub-server listening on http://" << endpoint.address().to_string() << ":"
                  << endpoint.port() << std::endl;

        std::vector<std::thread> threads;
        for (unsigned i = 1; i < options.ioThreads; ++i) threads.emplace_back([&ioc] { ioc.run(); });
        ioc.run();
        for (auto& t : threads) t.join();
        shutdownSignals.onSignal(nullptr);   // what it stops is about to go
        std::cout << "tlmhub-server stopped" << std::endl;
    } catch (const std::exception& e) {
        std::cerr << "tlmhub-server: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
