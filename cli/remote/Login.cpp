// remote login: a login session is used once, to create an API token; the token is what
// is stored, so the credentials file never holds the password.
#include "cli/remote/ApiClient.h"
#include "cli/remote/Arguments.h"
#include "cli/remote/Credentials.h"
#include "cli/remote/PasswordPrompt.h"
#include "cli/remote/RemoteCommands.h"

#include <cstdio>
#include <unistd.h>

namespace tlmhub::cli::remote {

namespace {

std::string hostName()
{
    char name[256] = {};
    return ::gethostname(name, sizeof name - 1) == 0 && name[0] ? name : "this computer";
}

std::string userName(const Arguments& args)
{
    if (args.has("user")) return args.value("user");
    if (args.has("password-stdin") || !standardInputIsTerminal())
        throw UsageError("--user NAME is needed when the password comes from standard input");
    std::fprintf(stderr, "user name: ");
    std::fflush(stderr);
    const std::optional<std::string> name = readLine();
    if (!name || name->empty()) throw UsageError("no user name given");
    return *name;
}

std::string password(const Arguments& args, const std::string& user, const Url& url)
{
    std::optional<std::string> password;
    if (args.has("password-stdin")) {
        password = readLine();
    } else {
        if (!standardInputIsTerminal())
            throw UsageError("no terminal to ask for the password; pass it on standard input with --password-stdin");
        password = readPassword("password for " + user + " at " + url.text() + ": ");
    }
    if (!password || password->empty()) throw std::runtime_error("no password given");
    return *password;
}

// The login session has done its job once the token exists (or cannot be made). Were the
// logout to fail, the session would still expire on its own.
void endSession(ApiClient& api)
{
    try {
        api.post("/auth/logout", nlohmann::json::object());
    } catch (const std::exception&) {
    }
}

} // namespace

int login(const std::vector<std::string>& argv)
{
    const Arguments args(argv, {"user", "token-name"}, {}, {"password-stdin"});
    if (args.positional().size() != 1) throw UsageError("login needs the server's URL");
    std::string error;
    const std::optional<Url> url = parseUrl(args.positional()[0], error);
    if (!url) throw UsageError(error);
    const std::string user = userName(args);
    const std::string secret = password(args, user, *url);
    const std::string tokenName = args.has("token-name") ? args.value("token-name") : "tlmhub-cli on " + hostName();

    ApiClient api(*url, "");
    const nlohmann::json session = api.post("/auth/login", nlohmann::json{{"username", user}, {"password", secret}});
    api.setToken(session.at("token").get<std::string>());
    std::string token;
    try {
        token = api.post("/tokens", nlohmann::json{{"name", tokenName}}).at("token").get<std::string>();
    } catch (const std::exception&) {
        endSession(api);
        throw;
    }
    endSession(api);
    saveCredentials({url->text(), token});
    std::printf("logged in to %s as %s: API token '%s' saved in %s\n", url->text().c_str(), user.c_str(),
                tokenName.c_str(), credentialsPath().c_str());
    return 0;
}

} // namespace tlmhub::cli::remote
