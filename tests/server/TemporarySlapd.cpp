#include "TemporarySlapd.h"

#include "ChildProcess.h"
#include "ServerHarness.h"

#include <arpa/inet.h>
#include <csignal>
#include <fstream>
#include <netinet/in.h>
#include <stdexcept>
#include <sys/socket.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace tlmhub::test {

namespace {

using Clock = std::chrono::steady_clock;

constexpr const char* kSlapd = "/usr/sbin/slapd";
constexpr const char* kSlapadd = "/usr/sbin/slapadd";
constexpr const char* kOpenssl = "/usr/bin/openssl";

bool accepts(unsigned short port)
{
    const int fd = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    if (fd < 0) return false;
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    addr.sin_port = htons(port);
    const bool ok = ::connect(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr) == 0;
    ::close(fd);
    return ok;
}

void write(const std::filesystem::path& file, const std::string& text)
{
    std::ofstream out(file, std::ios::binary);
    out << text;
    if (!out) throw std::runtime_error("TemporarySlapd: cannot write " + file.string());
}

std::string configuration(const std::filesystem::path& dir)
{
    const std::string d = dir.string();
    return "include /etc/ldap/schema/core.schema\n"
           "include /etc/ldap/schema/cosine.schema\n"
           "include /etc/ldap/schema/inetorgperson.schema\n"
           "pidfile " + d + "/slapd.pid\n"
           "modulepath /usr/lib/ldap\n"
           "moduleload back_mdb\n"
           "TLSCACertificateFile " + d + "/ca.pem\n"
           "TLSCertificateFile " + d + "/server.pem\n"
           "TLSCertificateKeyFile " + d + "/server.key\n"
           "database mdb\n"
           "maxsize 10485760\n"
           "suffix \"" + TemporarySlapd::kBase + "\"\n"
           "rootdn \"cn=admin," + TemporarySlapd::kBase + "\"\n"
           "directory " + d + "/db\n"
           "access to attrs=userPassword by anonymous auth by * none\n"
           "access to * by users read by * none\n";
}

} // namespace

void TemporarySlapd::run(const std::vector<std::string>& args, const std::string& step)
{
    if (::access(args[0].c_str(), X_OK) != 0)
        throw std::runtime_error("TemporarySlapd: " + args[0] + " is missing (apt-get install slapd openssl)");
    const int pid = spawn(args, mDir / "setup.log", mDir, RunAs{});
    const int status = waitUntil(pid, Clock::now() + std::chrono::seconds(60));
    if (status == -1) {
        ::kill(pid, SIGKILL);
        ::waitpid(pid, nullptr, 0);
    }
    if (status == -1 || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
        throw std::runtime_error("TemporarySlapd: " + step + " failed: " + tailOf(mDir / "setup.log", 2000));
}

TemporarySlapd::TemporarySlapd(const std::string& ldif)
{
    char pattern[] = "/tmp/tlmhub-slapd-XXXXXX";
    if (!::mkdtemp(pattern)) throw std::runtime_error("TemporarySlapd: mkdtemp failed");
    mDir = pattern;
    std::filesystem::create_directory(mDir / "db");
    const std::string d = mDir.string();
    const std::vector<std::string> ecKey = {"-newkey", "ec", "-pkeyopt", "ec_paramgen_curve:prime256v1", "-nodes"};
    auto with = [](std::vector<std::string> a, const std::vector<std::string>& b) {
        a.insert(a.end(), b.begin(), b.end());
        return a;
    };
    run(with({kOpenssl, "req", "-x509"}, with(ecKey, {"-keyout", d + "/ca.key", "-out", d + "/ca.pem", "-days", "2", "-subj", "/CN=tlmhub test CA"})), "the CA");
    run(with({kOpenssl, "req", "-x509"}, with(ecKey, {"-keyout", d + "/other-ca.key", "-out", d + "/other-ca.pem", "-days", "2", "-subj", "/CN=another CA"})), "the other CA");
    run(with({kOpenssl, "req"}, with(ecKey, {"-keyout", d + "/server.key", "-out", d + "/server.csr", "-subj", "/CN=127.0.0.1"})), "the server's key");
    write(mDir / "san.cnf", "subjectAltName=IP:127.0.0.1,DNS:localhost\n");
    run({kOpenssl, "x509", "-req", "-in", d + "/server.csr", "-CA", d + "/ca.pem", "-CAkey", d + "/ca.key", "-CAcreateserial",
         "-out", d + "/server.pem", "-days", "2", "-extfile", d + "/san.cnf"}, "the server's certificate");
    write(mDir / "slapd.conf", configuration(mDir));
    write(mDir / "data.ldif", std::string("dn: ") + kBase + "\nobjectClass: dcObject\nobjectClass: organization\no: Example\ndc: example\n\n" + ldif);
    run({kSlapadd, "-f", d + "/slapd.conf", "-l", d + "/data.ldif"}, "slapadd");

    const auto deadline = Clock::now() + std::chrono::seconds(30);
    for (int attempt = 0;; ++attempt) {
        mPort = freeLoopbackPort();
        mTlsPort = freeLoopbackPort();
        const std::string urls = startTlsUrl() + "/ " + ldapsUrl() + "/";
        // -d 0: in the foreground (no fork), quiet.
        mPid = spawn({kSlapd, "-f", d + "/slapd.conf", "-h", urls, "-d", "0"}, mDir / "slapd.log", mDir, RunAs{});
        while (Clock::now() < deadline && waitUntil(mPid, Clock::now()) == -1 && !(accepts(mPort) && accepts(mTlsPort)))
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        if (accepts(mPort) && accepts(mTlsPort)) return;
        // Ended (a port taken meanwhile) or too slow: again with other ports, while there is time.
        stopChild(mPid, std::chrono::seconds(0));
        mPid = -1;
        if (Clock::now() >= deadline || attempt == 3) {
            const std::string log = logTail();
            std::filesystem::remove_all(mDir);
            throw std::runtime_error("TemporarySlapd: slapd did not start: " + log);
        }
    }
}

TemporarySlapd::~TemporarySlapd()
{
    if (mPid > 0) stopChild(mPid, std::chrono::seconds(10));
    std::error_code ec;
    std::filesystem::remove_all(mDir, ec);
}

std::string TemporarySlapd::logTail() const
{
    return tailOf(mDir / "slapd.log", 2000);
}

} // namespace tlmhub::test
