#pragma once
// Test support for LDAP sign-in: a real OpenLDAP server (Debian's slapd) the test starts
// itself in a temporary directory, on two free loopback ports (ldaps:// and ldap:// with
// StartTLS), with a certificate from a CA made for it. Missing binaries throw (the test fails,
// naming the package to install); nothing is skipped.
#include <filesystem>
#include <string>
#include <vector>

namespace tlmhub::test {

class TemporarySlapd {
public:
    static constexpr const char* kBase = "dc=example,dc=org";

    // Makes the CA and certificate (openssl), loads `ldif` (entries under kBase, which is made
    // here) with slapadd, starts slapd and waits (at most 30 s) until it accepts connections.
    // Reading needs a bind; userPassword is only compared by binds.
    explicit TemporarySlapd(const std::string& ldif);
    // SIGTERM (SIGKILL if it has not ended after 10 s), then the directory is removed.
    ~TemporarySlapd();
    TemporarySlapd(const TemporarySlapd&) = delete;
    TemporarySlapd& operator=(const TemporarySlapd&) = delete;

    std::string ldapsUrl() const { return "ldaps://127.0.0.1:" + std::to_string(mTlsPort); }
    std::string startTlsUrl() const { return "ldap://127.0.0.1:" + std::to_string(mPort); }
    // The CA that signed the server's certificate, and one that did not.
    std::filesystem::path caFile() const { return mDir / "ca.pem"; }
    std::filesystem::path otherCaFile() const { return mDir / "other-ca.pem"; }
    std::string logTail() const;

private:
    void run(const std::vector<std::string>& args, const std::string& step);

    std::filesystem::path mDir;
    unsigned short mPort = 0, mTlsPort = 0;
    int mPid = -1;
};

} // namespace tlmhub::test
