#include "ChildProcess.h"

#include <chrono>
#include <csignal>
#include <cstring>
#include <stdexcept>
#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace tlmhub::test {

namespace {

std::vector<std::string> childEnvironment(const std::map<std::string, std::string>& extra)
{
    static const char* const controlled[] = {"TLMHUB_URL=", "TLMHUB_TOKEN=", "HOME=", "XDG_CONFIG_HOME=",
                                             "SSL_CERT_FILE=", "SSL_CERT_DIR="};
    std::vector<std::string> out;
    for (char** e = environ; *e; ++e) {
        bool keep = true;
        for (const char* name : controlled) keep = keep && std::strncmp(*e, name, std::strlen(name)) != 0;
        if (keep) out.emplace_back(*e);
    }
    for (const auto& [name, value] : extra) out.push_back(name + "=" + value);
    return out;
}

std::vector<char*> pointers(std::vector<std::string>& strings)
{
    std::vector<char*> out;
    for (std::string& s : strings) out.push_back(s.data());
    out.push_back(nullptr);
    return out;
}

} // namespace

CliResult runCli(const std::vector<std::string>& args, const std::map<std::string, std::string>& environment,
                 const std::string& input)
{
    std::vector<std::string> argv = {TLMHUB_CLI_BIN};
    argv.insert(argv.end(), args.begin(), args.end());
    return runProgram(argv, environment, input);
}

CliResult runProgram(const std::vector<std::string>& program, const std::map<std::string, std::string>& environment,
                     const std::string& input)
{
    std::vector<std::string> argvStrings = program;
    std::vector<std::string> envStrings = childEnvironment(environment);
    std::vector<char*> argv = pointers(argvStrings), envp = pointers(envStrings);
    int in[2], out[2], err[2];
    if (::pipe(in) != 0 || ::pipe(out) != 0 || ::pipe(err) != 0) throw std::runtime_error("pipe failed");
    const pid_t pid = ::fork();
    if (pid == 0) {
        ::dup2(in[0], STDIN_FILENO);
        ::dup2(out[1], STDOUT_FILENO);
        ::dup2(err[1], STDERR_FILENO);
        for (int fd : {in[0], in[1], out[0], out[1], err[0], err[1]}) ::close(fd);
        ::execvpe(argv[0], argv.data(), envp.data());
        ::_exit(127);
    }
    ::close(in[0]);
    ::close(out[1]);
    ::close(err[1]);
    // The input is small (a password line): it fits in the pipe's buffer.
    if (!input.empty() && ::write(in[1], input.data(), input.size()) != static_cast<ssize_t>(input.size()))
        throw std::runtime_error("cannot write the child's input");
    ::close(in[1]);

    CliResult result;
    std::string* sinks[2] = {&result.out, &result.err};
    pollfd fds[2] = {{out[0], POLLIN, 0}, {err[0], POLLIN, 0}};
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    bool killed = false;
    while (fds[0].fd >= 0 || fds[1].fd >= 0) {
        if (std::chrono::steady_clock::now() > deadline && !killed) {
            ::kill(pid, SIGKILL);
            killed = true;
        }
        if (::poll(fds, 2, 200) < 0) break;
        for (int i = 0; i < 2; ++i) {
            if (fds[i].fd < 0 || !(fds[i].revents & (POLLIN | POLLHUP | POLLERR))) continue;
            char buf[65536];
            const ssize_t n = ::read(fds[i].fd, buf, sizeof buf);
            if (n > 0) {
                sinks[i]->append(buf, static_cast<std::size_t>(n));
            } else {
                ::close(fds[i].fd);
                fds[i].fd = -1;
            }
        }
    }
    int status = 0;
    ::waitpid(pid, &status, 0);
    result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return result;
}

TlsProxy::TlsProxy(unsigned short backendPort, const std::filesystem::path& certDir)
{
    std::filesystem::create_directories(certDir);
    int out[2];
    if (::pipe(out) != 0) throw std::runtime_error("pipe failed");
    std::vector<std::string> argvStrings = {"python3", std::string(TLMHUB_SOURCE_DIR) + "/tests/tools/tls_proxy.py",
                                            "--backend", "127.0.0.1:" + std::to_string(backendPort), "--cert-dir",
                                            certDir.string()};
    std::vector<char*> argv = pointers(argvStrings);
    mPid = ::fork();
    if (mPid == 0) {
        ::dup2(out[1], STDOUT_FILENO);
        ::close(out[0]);
        ::close(out[1]);
        ::execvp(argv[0], argv.data());
        ::_exit(127);
    }
    ::close(out[1]);
    // "listening PORT" once the certificate is made (at most 30 s).
    std::string printed;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    while (std::chrono::steady_clock::now() < deadline && printed.find('\n') == std::string::npos) {
        pollfd p{out[0], POLLIN, 0};
        if (::poll(&p, 1, 200) <= 0) continue;
        char buf[256];
        const ssize_t n = ::read(out[0], buf, sizeof buf);
        if (n <= 0) break;
        printed.append(buf, static_cast<std::size_t>(n));
    }
    ::close(out[0]);
    if (printed.rfind("listening ", 0) != 0 || printed.find('\n') == std::string::npos) {
        ::kill(mPid, SIGKILL);
        ::waitpid(mPid, nullptr, 0);
        throw std::runtime_error("tls_proxy.py did not start; it printed: " + printed);
    }
    mPort = static_cast<unsigned short>(std::stoi(printed.substr(10)));
}

TlsProxy::~TlsProxy()
{
    ::kill(mPid, SIGTERM);
    ::waitpid(mPid, nullptr, 0);
}

unsigned short closedPort()
{
    const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t length = sizeof address;
    if (::bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0 ||
        ::getsockname(fd, reinterpret_cast<sockaddr*>(&address), &length) != 0)
        throw std::runtime_error("cannot bind a loopback port");
    ::close(fd);
    return ntohs(address.sin_port);
}

} // namespace tlmhub::test
