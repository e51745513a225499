#pragma once
// Start-up options of tlmhub-server: command-line flags over embedded defaults.
#include "core/ParameterEvaluator.h"
#include "server/auth/LdapDirectory.h"
#include "server/auth/PasswordHasher.h"
#include "server/jobs/Job.h"
#include "server/jobs/QueueNode.h"
#include "server/protocol/ProtocolConstants.generated.h"
#include "server/store/Storage.h"
#include "server/studies/StudyExecution.h"

#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

namespace tlmhub::server {

struct ServerOptions {
    std::string host = "127.0.0.1";
    unsigned short port = 8080;
    std::string dataDir = "data";
    // Empty: the embedded SQLite file <dataDir>/tlmhub.sqlite; else a postgresql:// URI.
    std::string database;
    // Non-empty: write a backup of the database to this file, or restore the database from
    // this file, and exit without serving (docs/storage.md).
    std::string backupFile, restoreFile;
    std::string webRoot = "web/dist";
    std::vector<std::string> exampleDirs;       // default: examples (if it exists)
    std::vector<std::string> componentLibs;     // shared libraries; administrator's flag only
    std::string fmuDir;                         // FMUs models may import; empty: none (fmu/FmuLoadPolicy.h)
    std::uintmax_t fmuCacheBytes = 256ull << 20;   // unpacked FMUs kept unused (fmu/FmuPackage.h)
    unsigned workers = 0;                       // simulation threads; 0 = one per core
    unsigned ioThreads = 4;                     // HTTP/WebSocket threads
    std::chrono::seconds tokenTtl{12 * 3600};
    std::chrono::seconds resultTtl{0};          // finished jobs kept this long; 0 = for ever
    std::size_t maxBodyBytes = protocol::kMaxBodyBytes;   // above limits.model.maxBytes: a JSON-wrapped model
    std::size_t wsQueueLimit = 256;             // messages queued per WebSocket before frames merge
    std::size_t wsQueueBytes = 16u << 20;       // bytes per WebSocket: frames resync, then it closes
    std::size_t diskReserveBytes = 8u << 20;    // given back when the disk is full (deleting works)
    // Non-empty: the file holding the secret nodes share (server/cluster/NodeSecret.h); a
    // WebSocket showing it may follow any job. Empty: no node may connect.
    std::string nodeSecretFile;
    // LDAP sign-in (docs/sign-in.md); off while ldap.url is empty. The service account's
    // password is read from ldapServicePasswordFile at start.
    LdapSettings ldap;
    std::string ldapServicePasswordFile;
    bool ldapCreateAccounts = true;
    // OpenID Connect sign-in (docs/sign-in.md): one entry per --oidc-issuer, the flags after it
    // its settings. Its client secret is read from the file at start.
    struct OidcProviderOption {
        std::string issuer, clientId, clientSecretFile, displayName;
        std::string roleClaim = "groups";   // the ID token claim roles are read from
        std::vector<std::pair<std::string, std::string>> roles;   // role, a value of that claim
    };
    std::vector<OidcProviderOption> oidcProviders;
    std::string oidcCaFile;           // CAs the providers' certificates chain to; empty: the system's
    bool oidcCreateAccounts = true;
    // LTI 1.3 tool (docs/sign-in.md): on with at least one key file. The tool's RSA keys are
    // read from the files at start; the first signs, all are published.
    std::vector<std::string> ltiKeyFiles;
    std::string ltiCaFile;            // CAs the platforms' certificates chain to; empty: the system's
    // The server's address as browsers reach it (https://tlmhub.uni.edu): where providers send
    // people back to (/api/v1/auth/oidc/{name}/callback), what platforms launch.
    std::string publicUrl;
    // --password-login off: only the accounts named here log in with a password of this
    // server's own (the administrator's way in); everyone else signs in through the directory
    // or a provider. Directory passwords and API tokens are not affected.
    bool passwordLogin = true;
    std::vector<std::string> localLoginUsers;
    // Cost of new password hashes; Minimal only for test servers (see --help).
    PasswordCost passwordCost = PasswordCost::Interactive;
    // Parameter expressions one evaluation pass may evaluate (core/ParameterEvaluator.h).
    std::size_t maxParameterEvaluations = ParameterEvaluator::kDefaultBudget;
    // Failed logins: per user name at one address, and per address (SECURITY.md). A lab of 40
    // behind one NAT mistyping a password each twice is 80 of the 500.
    int loginMaxFailures = 5;
    std::chrono::seconds loginWindow{60};
    // Lab check runs (pretests, hand-ins, reference runs) per user: users take turns.
    unsigned checkThreads = 0;   // check runs at once on this server; 0: one per core
    std::size_t maxRunningChecksPerUser = 2;
    std::size_t maxQueuedChecksPerUser = 10;
    // How long a pretest's reply waits for its run on the job queue before it answers 202
    // with where to ask again (docs/labs.md).
    std::chrono::milliseconds labWait{60'000};
    int addressMaxFailures = 500;
    std::chrono::seconds addressWindow{600};
    // --trusted-proxy: reverse proxies whose X-Forwarded-For names the client (CIDR ranges).
    std::vector<std::string> trustedProxies;
    JobLimits limits;
    // Live sessions (docs/live-sessions.md): run on the node the client is connected to.
    std::size_t maxLiveSessionsPerUser = 2;
    std::size_t maxLiveSessions = 64;                     // on this node
    std::chrono::milliseconds liveIdleTimeout{600'000};   // no message from the owner this long
    StudyLimits studyLimits;
    // Scale-out (docs/scale-out.md): what this node does, and how it takes part in the queue
    // the database holds for all nodes.
    std::string role = "all";                  // api, worker or all
    std::string nodeId;                        // default: host name, process id and time
    std::string nodeAddress;                   // http://host:port other nodes reach it at
    std::chrono::milliseconds leaseTime{10'000};
    int maxAttempts = 3;
};

// Where the options say the database is: options.database, else <dataDir>/tlmhub.sqlite.
StorageConfig storageConfig(const ServerOptions& options);

// This node's part in the job queue: its role, lease settings, and how many jobs it holds
// (one node holds as many as it time-slices; a worker among several about one per thread,
// so that idle workers get the rest). The id defaults to host-pid-time.
QueueNode queueNode(const ServerOptions& options, unsigned workers);

// Parses argv. On a bad flag returns false with `error`; `--help` sets `helpText`.
bool parseServerOptions(int argc, char** argv, ServerOptions& options, std::string& error,
                        std::string& helpText);

} // namespace tlmhub::server
