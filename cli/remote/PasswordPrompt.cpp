#include "cli/remote/PasswordPrompt.h"

#include <cstdio>
#include <iostream>
#include <termios.h>
#include <unistd.h>

namespace tlmhub::cli::remote {

namespace {

// Echo off for its lifetime; the terminal's settings come back however the read ends.
class EchoOff {
public:
    EchoOff() : mChanged(::tcgetattr(STDIN_FILENO, &mSaved) == 0)
    {
        if (!mChanged) return;
        termios quiet = mSaved;
        quiet.c_lflag &= ~static_cast<tcflag_t>(ECHO);
        mChanged = ::tcsetattr(STDIN_FILENO, TCSAFLUSH, &quiet) == 0;
    }
    ~EchoOff()
    {
        if (mChanged) ::tcsetattr(STDIN_FILENO, TCSAFLUSH, &mSaved);
    }
    EchoOff(const EchoOff&) = delete;
    EchoOff& operator=(const EchoOff&) = delete;

private:
    termios mSaved{};
    bool mChanged;
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
