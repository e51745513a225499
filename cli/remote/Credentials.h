#pragma once
// Where the remote commands find their server and API token: the credentials file that
// `tlmhub-cli remote login` writes, with TLMHUB_URL and TLMHUB_TOKEN taking precedence.
#include <filesystem>
#include <optional>
#include <string>

namespace tlmhub::cli::remote {

struct Credentials {
    std::string url;
    std::string token;
};

// $XDG_CONFIG_HOME/tlmhub/credentials, else ~/.config/tlmhub/credentials.
std::filesystem::path credentialsPath();

// Writes {"url", "token"} as JSON: the directory made 0700, the file written 0600 under a
// temporary name and renamed over the old one, so a reader never sees half a file.
// Throws std::runtime_error naming the path on failure.
void saveCredentials(const Credentials& credentials);

// The file's url and token, each replaced by TLMHUB_URL / TLMHUB_TOKEN when set; nullopt
// with `error` saying what is missing or wrong.
std::optional<Credentials> loadCredentials(std::string& error);

} // namespace tlmhub::cli::remote
