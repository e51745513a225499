#include "cli/remote/PasswordPrompt.h"

#include <csignal>
#include <cstdio>
#include <iostream>
#include <termios.h>
#include <unistd.h>

namespace tlmhub::cli::remote {

namespace {

termios gSaved;   // the settings from before echo was turned off (for the signal handler)

// Ctrl-C at the prompt: the terminal gets its echo back before the process ends.
extern "C" void restoreEchoAndDie(int signal)
{
    ::tcsetattr(STDIN_FILENO, TCSAFLUSH, &gSaved);
    std::signal(signal, SIG_DFL);
    std::raise(signal);
}

// Echo off for its lifetime; the terminal's settings come back however the read ends.
class EchoOff {
public:
    EchoOff()
    {
        if (::tcgetattr(STDIN_FILENO, &gSaved) != 0) return;
        mInterrupt = catchSignal(SIGINT);
        mTerminate = catchSignal(SIGTERM);
        termios quiet = gSaved;
        quiet.c_lflag &= ~static_cast<tcflag_t>(ECHO);
        mChanged = ::tcsetattr(STDIN_FILENO, TCSAFLUSH, &quiet) == 0;
        if (!mChanged) restoreSignals();
    }
    ~EchoOff()
    {
        if (!mChanged) return;
        ::tcsetattr(STDIN_FILENO, TCSAFLUSH, &gSaved);
        restoreSignals();
    }
    EchoOff(const EchoOff&) = delete;
    EchoOff& operator=(const EchoOff&) = delete;

private:
    using Handler = void (*)(int);
    // A signal the process ignores stays ignored.
    static Handler catchSignal(int signal)
    {
        const Handler previous = std::signal(signal, restoreEchoAndDie);
        if (previous == SIG_IGN) std::signal(signal, SIG_IGN);
        return previous;
    }
    void restoreSignals()
    {
        std::signal(SIGINT, mInterrupt);
        std::signal(SIGTERM, mTerminate);
    }

    bool mChanged = false;
    Handler mInterrupt = SIG_DFL;
    Handler mTerminate = SIG_DFL;
};

} // namespace

bool standardInputIsTerminal() { return ::isatty(STDIN_FILENO) == 1; }

std::optional<std::string> readLine()
{
    std::string line;
    if (!std::getline(std::cin, line) && line.empty()) return std::nullopt;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    return line;
}

std::optional<std::string> readPassword(const std::string& prompt)
{
    std::fprintf(stderr, "%s", prompt.c_str());
    std::fflush(stderr);
    std::optional<std::string> password;
    {
        EchoOff quiet;
        password = readLine();
    }
    std::fputc('\n', stderr);   // the Enter the terminal did not echo
    return password;
}

} // namespace tlmhub::cli::remote
