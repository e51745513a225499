#pragma once
// A TlmhubApp for the server fuzz targets, driven without a network: a fresh temporary data
// directory seeded with the small models in fuzz/models/, and a logged-in admin. Job workers are
// never started, so a submitted job stays queued and the fuzz loop never simulates.
#include "server/app/TlmhubApp.h"
#include "server/auth/TokenService.h"
#include "server/store/Storage.h"

#include <filesystem>
#include <memory>
#include <string>

namespace tlmhub::fuzz {

// A directory under the system temp dir, removed with everything in it on destruction.
class TempDir {
public:
    TempDir();
    ~TempDir();
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    const std::filesystem::path& path() const { return mPath; }

private:
    std::filesystem::path mPath;
};

class FuzzServer {
public:
    // One per process, made on first use (libFuzzer calls the target many times).
    static FuzzServer& instance();

    server::TlmhubApp& app() { return *mApp; }
    // The app's answer to `request` (handlers run on its pools: this waits for the reply).
    server::Response handle(const server::Request& request);
    // A bearer token of the admin; a new one if an input logged the last one out.
    const std::string& token();

private:
    FuzzServer();

    TempDir mDir;   // first member: removed after everything that has files in it
    std::unique_ptr<server::TlmhubApp> mApp;
    // A second storage on the app's database, so an input that logs out (or changes the
    // password) cannot lock the fuzzer out: a fresh token is issued without a login.
    std::unique_ptr<server::Storage> mStorage;
    std::unique_ptr<server::TokenService> mTokens;
    server::User mAdmin;
    std::string mToken;
};

// Aborts (a fuzzer finding) with the message on stderr.
[[noreturn]] void fail(const std::string& what);

} // namespace tlmhub::fuzz
