#pragma once
// Starting the servers tests need (PostgreSQL, slapd) as child processes: each in its own
// process group, taken along when the test process dies, its output in a log file.
#include <chrono>
#include <filesystem>
#include <string>
#include <sys/types.h>
#include <vector>

namespace tlmhub::test {

// The account a child server runs as. initdb and postgres refuse to run as root (CI runs the
// tests as root), so as root they run as `nobody`: the child process drops to it with
// setgid/setuid itself before exec (no runuser/setpriv needed), and its directory is chown'ed
// to it. Otherwise (and with drop false) as the current user.
struct RunAs {
    bool drop = false;
    uid_t uid = 0;
    gid_t gid = 0;
};
RunAs runAsNobodyIfRoot();

// The last `maxBytes` of `file`.
std::string tailOf(const std::filesystem::path& file, std::size_t maxBytes);

// Starts `args` (args[0] an absolute path) as `who` in `cwd`, stdout and stderr appended to
// `log`; it gets SIGQUIT when the thread that started it ends. Returns its pid.
int spawn(const std::vector<std::string>& args, const std::filesystem::path& log, const std::filesystem::path& cwd,
          const RunAs& who);

// Waits for `pid` until `deadline`; returns its wait status, or -1 (still running) at the deadline.
int waitUntil(int pid, std::chrono::steady_clock::time_point deadline);
// Stops `pid` and reaps it: SIGTERM, then SIGKILL when it has not ended within `grace`.
void stopChild(int pid, std::chrono::seconds grace);

} // namespace tlmhub::test
