#pragma once
// Reading the password for `tlmhub-cli remote login`: typed at a terminal without echo, or
// one line from standard input (--password-stdin) for scripts.
#include <optional>
#include <string>

namespace tlmhub::cli::remote {

bool standardInputIsTerminal();

// One line of standard input without its line end; nullopt at the end of the input.
std::optional<std::string> readLine();

// Shows `prompt` on stderr and reads a line from the terminal with echo turned off.
std::optional<std::string> readPassword(const std::string& prompt);

} // namespace tlmhub::cli::remote
