#include "server/app/ServerOptions.h"

#include "server/http/TrustedProxies.h"
#include "server/jobs/JobQueue.h"

#include <unistd.h>

#include <charconv>
#include <ctime>
#include <filesystem>
#include <string>

namespace tlmhub::server {

namespace {

// The body limit's default is the protocol's (x-constants of protocol/messages.schema.json).
const std::string kHelp = std::string(
    "usage: tlmhub-server [options]\n"
    "  --listen HOST:PORT       address to listen on (default 127.0.0.1:8080; port 0 = any free)\n"
    "  --data-dir DIR           SQLite database directory (default ./data)\n"
    "  --database URI           a PostgreSQL database (postgresql://user@host:port/db) instead\n"
    "                           of SQLite in the data directory (docs/storage.md)\n"
    "  --backup FILE            write a consistent copy of the SQLite database to FILE (a new\n"
    "                           file) and exit; works while a server runs on the data directory\n"
    "  --restore FILE           replace the SQLite database with the backup FILE and exit (the\n"
    "                           server must be stopped; the old file is kept as\n"
    "                           tlmhub.sqlite.before-restore)\n"
    "  --web-root DIR           built web app to serve (default web/dist)\n"
    "  --examples-dir DIR       seed *.hmf found here as examples on first sight (repeatable;\n"
    "                           default ./examples)\n"
    "  --workers N              simulation worker threads (default: number of cores)\n"
    "  --trusted-proxy CIDR     a reverse proxy (address or range, repeatable) whose\n"
    "                           X-Forwarded-For names the client for the failed-login limits\n"
    "  --io-threads N           threads serving HTTP and WebSocket connections (default 4);\n"
    "                           they only read, route and write: model work runs beside them\n"
    "  --component-lib PATH     load extra components from a shared library (repeatable)\n"
    "  --fmu-dir DIR            models may import FMUs (FMIWrapper) from this directory only\n"
    "                           (default: no FMUs)\n"
    "  --token-ttl SECONDS      login token lifetime (default 43200)\n"
    "  --max-steps N            steps per job (default 50000000)\n"
    "  --max-log-samples N      log samples per job (default 100000)\n"
    "  --max-wall-seconds S     wall time per job (default 300)\n"
    "  --max-running-per-user N jobs running at once per user (default 2)\n"
    "  --max-queued-per-user N  jobs waiting per user (default 20)\n"
    "  --max-stored-bytes-per-user N  results kept per user (default 1073741824)\n"
    "  --max-unpinned-runs-per-model N  a model's finished runs that keep their results\n"
    "                           unless pinned; older ones lose them (default 20)\n"
    "  --max-live-sessions-per-user N  live sessions a user runs at once (default 2)\n"
    "  --max-live-sessions N    live sessions on this node (default 64)\n"
    "  --live-idle-timeout SECONDS  a live session whose owner sends nothing this long ends\n"
    "                           (default 600)\n"
    "  --max-study-runs N       runs per study (default 10000)\n"
    "  --max-studies-per-user N studies queued or running per user (default 2)\n"
    "  --check-threads N        lab check runs at once (default: number of cores)\n"
    "  --max-running-checks-per-user N  a user's lab check runs (pretests, hand-ins,\n"
    "                           reference runs) at once; users take turns (default 2)\n"
    "  --max-queued-checks-per-user N   a user's check runs waiting (default 10)\n"
    "  --lab-wait-seconds S     a pretest's reply waits this long for its run on the job\n"
    "                           queue, then answers 202 with where to ask again (default 60)\n"
    "  --max-study-bytes N      run results one study keeps (default 536870912)\n") +
    "  --max-body-bytes N       request body limit (default " + std::to_string(protocol::kMaxBodyBytes) + ")\n" +
    "  --max-model-bytes N      size of a model's .hmf (default 16777216)\n"
    "  --max-model-components N components and subsystems in a model (default 20000)\n"
    "  --max-model-depth N      subsystems nested in subsystems (default 16)\n"
    "  --max-model-fmus N       imported FMUs (FMIWrapper components) in a model (default 64)\n"
    "  --fmu-cache-bytes N      unpacked FMUs kept for the next load or compile while no model\n"
    "                           holds them (default 268435456)\n"
    "  --max-parameter-evaluations N  parameter expressions evaluated to check or compile a\n"
    "                           model (default " + std::to_string(ParameterEvaluator::kDefaultBudget) + ")\n" +
    "  --max-ws-queue-messages N  messages waiting for a slow WebSocket client; past it a\n"
    "                           job's new samples merge into its waiting frame (default 256)\n"
    "  --max-ws-queue-bytes N   bytes waiting for a WebSocket client: past it a job's waiting\n"
    "                           frames give way to event.resync, and a client whose replies\n"
    "                           alone pass it is disconnected (default 16777216)\n"
    "  --disk-reserve-bytes N   space kept beside the database and given back when the disk\n"
    "                           is full, so logging in and deleting still work (default 8388608)\n"
    "  --result-ttl SECONDS     delete unpinned finished jobs and their results this long after\n"
    "                           they finish (default 0: keep them until their owner deletes them)\n"
    "  --password-hash-cost interactive|minimal  argon2id cost of new password hashes\n"
    "                           (default interactive: about 0.1 s and 64 MiB each); minimal is\n"
    "                           for test servers only: its hashes take microseconds to guess\n"
    "scale-out (docs/scale-out.md):\n"
    "  --role api|worker|all    api: serve clients, run no jobs; worker: run jobs from the\n"
    "                           shared queue, serve only health and node connections; all:\n"
    "                           both (default)\n"
    "  --node-id NAME           this node's name in the nodes table (default: host-pid-time)\n"
    "  --node-address URL       http://host:port where other nodes reach this one\n"
    "  --lease-seconds S        a claimed job's lease, renewed every S/3 (default 10)\n"
    "  --max-attempts N         claims before a job whose node keeps stopping is dead (default 3)\n"
    "  --node-secret-file PATH  the secret this deployment's nodes share (at least 32 bytes,\n"
    "                           readable by its owner only): a WebSocket that shows it as\n"
    "                           'Authorization: Bearer tlmhub-node.<secret>' may follow any job\n"
    "  --ldap-url URL           sign in with a directory's names and passwords: ldaps://host, or\n"
    "                           ldap://host with StartTLS; the certificate is always verified\n"
    "  --ldap-bind-dn TEMPLATE  the user's DN, {username} in it (uid={username},ou=people,...)\n"
    "  --ldap-search-base DN    else: search the user under DN as a service account ...\n"
    "  --ldap-search-filter F   ... with this filter (default (uid={username})) ...\n"
    "  --ldap-service-dn DN     ... binding as DN ...\n"
    "  --ldap-service-password-file PATH  ... with the password in PATH (mode 0600)\n"
    "  --ldap-ca-file PATH      CAs that sign the directory's certificate (default: the system's)\n"
    "  --ldap-role-group ROLE=DN  members of group DN get server role ROLE (repeatable)\n"
    "  --ldap-create-accounts on|off  make an account on a person's first sign-in (default on)\n"
    "  --ldap-timeout S         limit of each connection and operation (default 5)\n"
    "  --oidc-issuer URL        sign in with an OpenID provider (https://...; repeatable: each\n"
    "                           starts a provider, the --oidc-* flags after it are its own)\n"
    "  --oidc-client-id ID      the client id this server has at the provider\n"
    "  --oidc-client-secret-file PATH  the client's secret (mode 0600)\n"
    "  --oidc-name TEXT         the button's \"Sign in with TEXT\"\n"
    "  --oidc-role ROLE=VALUE   people whose role claim holds VALUE get server role ROLE\n"
    "  --oidc-role-claim NAME   the ID token claim roles come from (default groups)\n"
    "  --oidc-ca-file PATH      CAs of the providers' certificates (default: the system's)\n"
    "  --oidc-create-accounts on|off  make an account on a person's first sign-in (default on)\n"
    "  --lti-key-file PATH      be an LTI 1.3 tool with the RSA key in PATH (mode 0600;\n"
    "                           repeatable: the first signs, all are published)\n"
    "  --lti-ca-file PATH       CAs of the learning platforms' certificates (default: the system's)\n"
    "  --public-url URL         the server's address as browsers reach it (needed by --oidc-issuer\n"
    "                           and --lti-key-file)\n"
    "  --password-login on|off  off: this server's own passwords log in only the accounts\n"
    "                           named by --local-login-user (default on)\n"
    "  --local-login-user NAME  an account that keeps its password login (repeatable)\n"
    "environment: TLMHUB_ADMIN_PASSWORD sets the password of 'admin' on first start\n";

template <typename T>
bool parseNumber(const std::string& text, T& out)
{
    const char* end = text.data() + text.size();
    auto [ptr, ec] = std::from_chars(text.data(), end, out);
    return ec == std::errc() && ptr == end;
}

} // namespace

bool parseServerOptions(int argc, char** argv, ServerOptions& o, std::string& error,
                        std::string& helpText)
{
    bool examplesGiven = false;
    for (int i = 1; i < argc; ++i) {
        const std::string flag = argv[i];
        if (flag == "--help" || flag == "-h") {
            helpText = kHelp;
            return true;
        }
        if (i + 1 >= argc) {
            error = "option " + flag + " needs a value (see --help)";
            return false;
        }
        const std::string value = argv[++i];
        bool ok = true;
        if (flag == "--listen") {
            const auto colon = value.rfind(':');
            ok = colon != std::string::npos && colon > 0 &&
                 parseNumber(value.substr(colon + 1), o.port);
            if (ok) o.host = value.substr(0, colon);
        } else if (flag == "--data-dir") {
            o.dataDir = value;
        } else if (flag == "--database") {
            if (!isPostgresUri(value)) {
                error = "--database takes a postgresql:// URI; SQLite is chosen with --data-dir";
                return false;
            }
            o.database = value;
        } else if (flag == "--backup") {
            o.backupFile = value;
        } else if (flag == "--restore") {
            o.restoreFile = value;
        } else if (flag == "--web-root") {
            o.webRoot = value;
        } else if (flag == "--examples-dir") {
            o.exampleDirs.push_back(value);
            examplesGiven = true;
        } else if (flag == "--component-lib") {
            o.componentLibs.push_back(value);
        } else if (flag == "--fmu-dir") {
            o.fmuDir = value;
        } else if (flag == "--workers") {
            ok = parseNumber(value, o.workers);
        } else if (flag == "--check-threads") {
            ok = parseNumber(value, o.checkThreads) && o.checkThreads > 0;
        } else if (flag == "--max-running-checks-per-user") {
            ok = parseNumber(value, o.maxRunningChecksPerUser) && o.maxRunningChecksPerUser > 0;
        } else if (flag == "--max-queued-checks-per-user") {
            ok = parseNumber(value, o.maxQueuedChecksPerUser) && o.maxQueuedChecksPerUser > 0;
        } else if (flag == "--lab-wait-seconds") {
            double s = 0;
            ok = parseNumber(value, s) && s >= 0 && s <= 600;
            o.labWait = std::chrono::milliseconds(static_cast<long long>(s * 1000));
        } else if (flag == "--trusted-proxy") {
            ok = TrustedProxies().add(value);
            o.trustedProxies.push_back(value);
        } else if (flag == "--io-threads") {
            ok = parseNumber(value, o.ioThreads) && o.ioThreads > 0;
        } else if (flag == "--token-ttl") {
            long long s = 0;
            ok = parseNumber(value, s);
            o.tokenTtl = std::chrono::seconds(s);
        } else if (flag == "--max-live-sessions-per-user") {
            ok = parseNumber(value, o.maxLiveSessionsPerUser) && o.maxLiveSessionsPerUser > 0;
        } else if (flag == "--max-live-sessions") {
            ok = parseNumber(value, o.maxLiveSessions) && o.maxLiveSessions > 0;
        } else if (flag == "--live-idle-timeout") {
            // Seconds, fractions allowed (a test waits about one).
            double s = 0;
            ok = parseNumber(value, s) && s > 0 && s <= 86400;
            o.liveIdleTimeout = std::chrono::milliseconds(static_cast<long long>(s * 1000));
        } else if (flag == "--max-steps") {
            ok = parseNumber(value, o.limits.maxSteps);
        } else if (flag == "--max-log-samples") {
            ok = parseNumber(value, o.limits.maxLogSamples);
        } else if (flag == "--max-wall-seconds") {
            ok = parseNumber(value, o.limits.maxWallSeconds);
        } else if (flag == "--max-study-runs") {
            ok = parseNumber(value, o.studyLimits.maxRuns) && o.studyLimits.maxRuns > 0;
        } else if (flag == "--max-studies-per-user") {
            ok = parseNumber(value, o.studyLimits.maxActivePerUser) && o.studyLimits.maxActivePerUser > 0;
        } else if (flag == "--max-study-bytes") {
            ok = parseNumber(value, o.studyLimits.maxStoredBytes);
        } else if (flag == "--max-running-per-user") {
            ok = parseNumber(value, o.limits.maxRunningPerUser);
        } else if (flag == "--max-queued-per-user") {
            ok = parseNumber(value, o.limits.maxQueuedPerUser);
        } else if (flag == "--max-unpinned-runs-per-model") {
            ok = parseNumber(value, o.limits.maxUnpinnedRunsPerModel) && o.limits.maxUnpinnedRunsPerModel >= 0;
        } else if (flag == "--max-stored-bytes-per-user") {
            ok = parseNumber(value, o.limits.maxStoredBytesPerUser);
        } else if (flag == "--result-ttl") {
            long long s = 0;
            ok = parseNumber(value, s) && s >= 0;
            o.resultTtl = std::chrono::seconds(s);
        } else if (flag == "--max-body-bytes") {
            ok = parseNumber(value, o.maxBodyBytes);
        } else if (flag == "--disk-reserve-bytes") {
            ok = parseNumber(value, o.diskReserveBytes);
        } else if (flag == "--max-model-bytes") {
            ok = parseNumber(value, o.limits.model.maxBytes);
        } else if (flag == "--max-model-components") {
            ok = parseNumber(value, o.limits.model.maxComponents);
        } else if (flag == "--max-parameter-evaluations") {
            ok = parseNumber(value, o.maxParameterEvaluations) && o.maxParameterEvaluations > 0;
        } else if (flag == "--max-model-depth") {
            ok = parseNumber(value, o.limits.model.maxDepth);
        } else if (flag == "--max-model-fmus") {
            ok = parseNumber(value, o.limits.model.maxFmus);
        } else if (flag == "--fmu-cache-bytes") {
            ok = parseNumber(value, o.fmuCacheBytes);
        } else if (flag == "--max-ws-queue-messages") {
            ok = parseNumber(value, o.wsQueueLimit) && o.wsQueueLimit > 0;
        } else if (flag == "--ldap-url") {
            ok = value.starts_with("ldaps://") || value.starts_with("ldap://");
            o.ldap.url = value;
        } else if (flag == "--ldap-bind-dn") {
            ok = value.find("{username}") != std::string::npos;
            o.ldap.bindDnTemplate = value;
        } else if (flag == "--ldap-search-base") {
            o.ldap.searchBase = value;
        } else if (flag == "--ldap-search-filter") {
            ok = value.find("{username}") != std::string::npos && value.starts_with("(") && value.ends_with(")");
            o.ldap.searchFilter = value;
        } else if (flag == "--ldap-service-dn") {
            o.ldap.serviceDn = value;
        } else if (flag == "--ldap-service-password-file") {
            o.ldapServicePasswordFile = value;
        } else if (flag == "--ldap-ca-file") {
            o.ldap.caFile = value;
        } else if (flag == "--ldap-role-group") {
            const std::size_t equals = value.find('=');
            const std::string role = value.substr(0, std::min(equals, value.size()));
            ok = equals != std::string::npos && isValidRole(role) && equals + 1 < value.size();
            if (ok) o.ldap.roleGroups.push_back({.role = role, .groupDn = value.substr(equals + 1)});
        } else if (flag == "--ldap-create-accounts") {
            ok = value == "on" || value == "off";
            o.ldapCreateAccounts = value == "on";
        } else if (flag == "--oidc-issuer") {
            ok = value.starts_with("https://") && value.size() > 8;
            o.oidcProviders.emplace_back().issuer = value;
        } else if (flag == "--oidc-client-id" || flag == "--oidc-client-secret-file" || flag == "--oidc-name" ||
                   flag == "--oidc-role" || flag == "--oidc-role-claim") {
            if (o.oidcProviders.empty()) {
                error = flag + " belongs to a provider: give --oidc-issuer first";
                return false;
            }
            auto& provider = o.oidcProviders.back();
            ok = !value.empty();
            if (flag == "--oidc-client-id") provider.clientId = value;
            else if (flag == "--oidc-client-secret-file") provider.clientSecretFile = value;
            else if (flag == "--oidc-name") provider.displayName = value;
            else if (flag == "--oidc-role-claim") provider.roleClaim = value;
            else {
                const std::size_t equals = value.find('=');
                const std::string role = value.substr(0, std::min(equals, value.size()));
                ok = equals != std::string::npos && isValidRole(role) && equals + 1 < value.size();
                if (ok) provider.roles.emplace_back(role, value.substr(equals + 1));
            }
        } else if (flag == "--oidc-ca-file") {
            o.oidcCaFile = value;
        } else if (flag == "--lti-key-file") {
            ok = !value.empty();
            o.ltiKeyFiles.push_back(value);
        } else if (flag == "--lti-ca-file") {
            o.ltiCaFile = value;
        } else if (flag == "--oidc-create-accounts") {
            ok = value == "on" || value == "off";
            o.oidcCreateAccounts = value == "on";
        } else if (flag == "--public-url") {
            ok = (value.starts_with("https://") || value.starts_with("http://")) && !value.ends_with("/");
            o.publicUrl = value;
        } else if (flag == "--password-login") {
            ok = value == "on" || value == "off";
            o.passwordLogin = value == "on";
        } else if (flag == "--local-login-user") {
            ok = !value.empty();
            o.localLoginUsers.push_back(value);
        } else if (flag == "--ldap-timeout") {
            double s = 0;
            ok = parseNumber(value, s) && s > 0 && s <= 300;
            o.ldap.timeout = std::chrono::milliseconds(static_cast<long long>(s * 1000));
        } else if (flag == "--node-secret-file") {
            o.nodeSecretFile = value;
        } else if (flag == "--max-ws-queue-bytes") {
            ok = parseNumber(value, o.wsQueueBytes);
        } else if (flag == "--password-hash-cost") {
            ok = value == "interactive" || value == "minimal";
            o.passwordCost = value == "minimal" ? PasswordCost::Minimal : PasswordCost::Interactive;
        } else if (flag == "--role") {
            ok = value == "api" || value == "worker" || value == "all";
            o.role = value;
        } else if (flag == "--node-id") {
            ok = !value.empty() && value.size() <= 200;
            o.nodeId = value;
        } else if (flag == "--node-address") {
            ok = value.starts_with("http://") || value.starts_with("https://");
            o.nodeAddress = value;
        } else if (flag == "--lease-seconds") {
            double s = 0;
            ok = parseNumber(value, s) && s >= 0.3 && s <= 3600;
            o.leaseTime = std::chrono::milliseconds(static_cast<long long>(s * 1000));
        } else if (flag == "--max-attempts") {
            ok = parseNumber(value, o.maxAttempts) && o.maxAttempts >= 1;
        } else {
            error = "unknown option " + flag + " (see --help)";
            return false;
        }
        if (!ok) {
            error = "bad value '" + value + "' for " + flag;
            return false;
        }
    }
    if (!o.backupFile.empty() && !o.restoreFile.empty()) {
        error = "--backup and --restore cannot be given together";
        return false;
    }
    if (!o.ldap.url.empty() && o.ldap.bindDnTemplate.empty()
        && (o.ldap.searchBase.empty() || o.ldap.serviceDn.empty() || o.ldapServicePasswordFile.empty())) {
        error = "--ldap-url needs --ldap-bind-dn, or --ldap-search-base with --ldap-service-dn and "
                "--ldap-service-password-file";
        return false;
    }
    for (const auto& provider : o.oidcProviders)
        if (provider.clientId.empty() || provider.clientSecretFile.empty() || provider.displayName.empty()) {
            error = "--oidc-issuer " + provider.issuer + " needs --oidc-client-id, --oidc-client-secret-file and --oidc-name";
            return false;
        }
    if (!o.oidcProviders.empty() && o.publicUrl.empty()) {
        error = "--oidc-issuer needs --public-url: the address providers send people back to";
        return false;
    }
    if (!o.ltiKeyFiles.empty() && o.publicUrl.empty()) {
        error = "--lti-key-file needs --public-url: the address learning platforms launch";
        return false;
    }
    if (!o.passwordLogin && o.localLoginUsers.empty() && o.ldap.url.empty() && o.oidcProviders.empty()) {
        error = "--password-login off would let nobody log in: name the administrator's account with "
                "--local-login-user, or give --ldap-url or --oidc-issuer";
        return false;
    }
    if (!examplesGiven && std::filesystem::is_directory("examples"))
        o.exampleDirs.push_back("examples");
    return true;
}

QueueNode queueNode(const ServerOptions& options, unsigned workers)
{
    QueueNode node;
    node.id = options.nodeId;
    if (node.id.empty()) {
        char host[256] = {};
        gethostname(host, sizeof host - 1);
        node.id = std::string(host) + "-" + std::to_string(getpid()) + "-" + std::to_string(std::time(nullptr));
    }
    node.role = options.role;
    node.address = options.nodeAddress;
    node.runsJobs = options.role != "api";
    node.releaseOnShutdown = options.role == "worker";
    node.leaseTime = options.leaseTime;
    node.maxAttempts = options.maxAttempts;
    if (options.role == "worker") {
        node.heldLimit = workers;
        node.firstSliceHeldLimit = 2 * std::size_t(workers);
    } else {
        node.heldLimit = node.firstSliceHeldLimit = JobQueue::kMaxStartedJobs;
    }
    return node;
}

StorageConfig storageConfig(const ServerOptions& options)
{
    StorageConfig config;
    config.database = !options.database.empty()
                          ? options.database
                          : (std::filesystem::path(options.dataDir) / "tlmhub.sqlite").string();
    config.reserveBytes = options.diskReserveBytes;
    return config;
}

} // namespace tlmhub::server
