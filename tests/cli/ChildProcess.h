#pragma once
// The processes the remote CLI tests start: tlmhub-cli itself, run to its end with its
// output captured, and the TLS proxy (tests/tools/tls_proxy.py) in front of a server.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace tlmhub::test {

struct CliResult {
    int exitCode = -1;     // -1: killed (signal or the time limit)
    std::string out;       // stdout
    std::string err;       // stderr
};

// Runs `argv` (the program looked up on PATH), feeding `input` to its stdin. Its environment
// is this process's without the variables the remote commands read (TLMHUB_URL,
// TLMHUB_TOKEN, HOME, XDG_CONFIG_HOME, SSL_CERT_FILE, SSL_CERT_DIR), plus `environment`.
// Killed after 120 s.
CliResult runProgram(const std::vector<std::string>& argv, const std::map<std::string, std::string>& environment = {},
                     const std::string& input = "");

// runProgram of tlmhub-cli with `args`.
CliResult runCli(const std::vector<std::string>& args, const std::map<std::string, std::string>& environment = {},
                 const std::string& input = "");

// tls_proxy.py forwarding to 127.0.0.1:`backendPort`; its certificate is `certDir`/cert.pem.
class TlsProxy {
public:
    TlsProxy(unsigned short backendPort, const std::filesystem::path& certDir);
    ~TlsProxy();
    TlsProxy(const TlsProxy&) = delete;
    TlsProxy& operator=(const TlsProxy&) = delete;
    unsigned short port() const { return mPort; }

private:
    int mPid = -1;
    unsigned short mPort = 0;
};

// A loopback port nothing listens on (bound, then released).
unsigned short closedPort();

} // namespace tlmhub::test
