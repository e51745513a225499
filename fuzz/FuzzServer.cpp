#include "fuzz/FuzzServer.h"

#include "server/auth/PasswordHasher.h"

#include <cstdio>
#include <cstdlib>
#include <future>
#include <iostream>

namespace tlmhub::fuzz {

namespace fs = std::filesystem;

TempDir::TempDir()
{
    std::string pattern = (fs::temp_directory_path() / "tlmhub-fuzz-XXXXXX").string();
    if (!mkdtemp(pattern.data())) fail("cannot create a temporary directory");
    mPath = pattern;
}

TempDir::~TempDir()
{
    std::error_code ec;
    fs::remove_all(mPath, ec);
}

void fail(const std::string& what)
{
    std::cerr << "fuzz check failed: " << what << std::endl;
    std::abort();
}

FuzzServer& FuzzServer::instance()
{
    static FuzzServer server;
    return server;
}

FuzzServer::FuzzServer()
{
    // Before the first hash (bootstrap's admin, the login decoy): inputs that create users or
    // log in would otherwise take 0.1 s each.
    server::setPasswordCost(server::PasswordCost::Minimal);
    server::ServerOptions options;
    options.dataDir = (mDir.path() / "data").string();
    options.webRoot = (mDir.path() / "web").string();   // empty: no web app served
    // Small models of our own rather than the shared examples: opening and serialising a
    // large model would take most of each run (65 runs/s with the examples), and the hmf
    // target covers the loader.
    options.exampleDirs = {TLMHUB_FUZZ_MODELS_DIR};
    if (!fs::is_directory(options.exampleDirs[0])) fail("no example models at " + options.exampleDirs[0]);
    options.workers = 1;
    mApp = std::make_unique<server::TlmhubApp>(options);
    // The admin gets a generated password nobody knows, so no input can log in as it or
    // change its password; the fuzzer's tokens come from mTokens.
    unsetenv("TLMHUB_ADMIN_PASSWORD");
    std::string log;
    if (!mApp->bootstrap(log)) fail("bootstrap did not create the admin");

    mStorage = server::openStorage(server::storageConfig(options));
    mTokens = std::make_unique<server::TokenService>(mStorage->sessions(), mStorage->users(), options.tokenTtl);
    const auto admin = mStorage->users().findByName("admin");
    if (!admin) fail("no admin user after bootstrap");
    mAdmin = *admin;
    mToken = mTokens->issue(mAdmin).token;
}

server::Response FuzzServer::handle(const server::Request& request)
{
    std::promise<server::Response> answered;
    std::future<server::Response> response = answered.get_future();
    mApp->handle({request, "127.0.0.1"}, [&answered](server::Response r) { answered.set_value(std::move(r)); });
    return response.get();
}

const std::string& FuzzServer::token()
{
    if (!mTokens->validate(mToken)) mToken = mTokens->issue(mAdmin).token;
    return mToken;
}

} // namespace tlmhub::fuzz
