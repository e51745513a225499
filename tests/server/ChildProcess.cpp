#include "ChildProcess.h"

#include <cerrno>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <grp.h>
#include <pwd.h>
#include <sstream>
#include <stdexcept>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace tlmhub::test {

RunAs runAsNobodyIfRoot()
{
    RunAs r;
    if (::geteuid() != 0) return r;
    const passwd* pw = ::getpwnam("nobody");
    if (pw == nullptr) throw std::runtime_error("running as root and there is no user 'nobody' to run a server as");
    r.drop = true;
    r.uid = pw->pw_uid;
    r.gid = pw->pw_gid;
    return r;
}

std::string tailOf(const std::filesystem::path& file, std::size_t maxBytes)
{
    std::ifstream in(file, std::ios::binary);
    if (!in) return "(no log at " + file.string() + ")";
    std::ostringstream s;
    s << in.rdbuf();
    std::string text = s.str();
    if (text.size() > maxBytes) text = "..." + text.substr(text.size() - maxBytes);
    return text;
}

// Starts `args` (args[0] an absolute path) as `who` in `cwd`, stdout and stderr appended to
// `log`. Everything the child needs is prepared before fork (the test process has threads).
int spawn(const std::vector<std::string>& args, const std::filesystem::path& log,
          const std::filesystem::path& cwd, const RunAs& who)
{
    const int logFd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
    if (logFd < 0) throw std::runtime_error("cannot open " + log.string() + ": " + std::strerror(errno));
    if (who.drop && ::fchown(logFd, who.uid, who.gid) != 0) {
        ::close(logFd);
        throw std::runtime_error("cannot chown " + log.string());
    }
    std::vector<std::string> copy = args;
    std::vector<char*> argv;
    for (auto& a : copy) argv.push_back(a.data());
    argv.push_back(nullptr);
    const std::string dir = cwd.string();
    const pid_t parent = ::getpid();
    const pid_t pid = ::fork();
    if (pid < 0) {
        ::close(logFd);
        throw std::runtime_error("fork failed");
    }
    if (pid == 0) {
        ::dup2(logFd, STDOUT_FILENO);
        ::dup2(logFd, STDERR_FILENO);
        ::setpgid(0, 0); // a Ctrl-C in the terminal reaches the test, not the server directly
        if (who.drop && (::setgroups(0, nullptr) != 0 || ::setgid(who.gid) != 0 || ::setuid(who.uid) != 0)) {
            static const char msg[] = "cannot drop to user nobody\n";
            (void)!::write(STDERR_FILENO, msg, sizeof msg - 1);
            ::_exit(126);
        }
        // A test process that dies without its destructors (a crash, a sanitizer abort, ctest's
        // timeout) takes its server along (SIGQUIT: immediate shutdown) instead of leaving it
        // running. (Linux sends it when the thread that forked ends: construct the server's owner
        // on a thread that lives as long as it.) Set after the user change, which clears it;
        // the parent may already be gone by then.
        if (::prctl(PR_SET_PDEATHSIG, SIGQUIT) != 0 || ::getppid() != parent) ::_exit(126);
        if (::chdir(dir.c_str()) != 0) ::_exit(126);
        ::execv(argv[0], argv.data());
        static const char msg[] = "exec failed\n";
        (void)!::write(STDERR_FILENO, msg, sizeof msg - 1);
        ::_exit(127);
    }
    ::close(logFd);
    return pid;
}

// Waits for `pid` until `deadline`; returns its wait status, or -1 (still running) at the deadline.
int waitUntil(int pid, std::chrono::steady_clock::time_point deadline)
{
    for (;;) {
        int status = 0;
        const pid_t r = ::waitpid(pid, &status, WNOHANG);
        if (r == pid) return status;
        if (r < 0 && errno != EINTR) return 0;
        if (std::chrono::steady_clock::now() >= deadline) return -1;
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
}

void stopChild(int pid, std::chrono::seconds grace)
{
    ::kill(pid, SIGTERM);
    if (waitUntil(pid, std::chrono::steady_clock::now() + grace) == -1) {
        ::kill(pid, SIGKILL);
        ::waitpid(pid, nullptr, 0);
    }
}

} // namespace tlmhub::test
