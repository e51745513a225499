// `--password-login off` (issue 43 item 1): where people sign in through the university, this
// server's own passwords log in only the accounts named by `--local-login-user` (the
// administrator's way in); the others get a refusal that says how to sign in instead, and a
// server started so that nobody could log in refuses to start.
#include "ServerHarness.h"

#include "server/app/ServerOptions.h"

#include <gtest/gtest.h>

namespace tlmhub::test {
namespace {

HttpReply passwordLogin(const ServerProcess& server, const std::string& user, const std::string& password)
{
    HttpClient client(server.port());
    return client.post("/api/v1/auth/login", {{"username", user}, {"password", password}});
}

} // namespace

TEST(PasswordLoginOff, OnlyTheNamedAccountsLogInWithAPasswordOfTheServersOwn)
{
    ServerProcess server(freshTempDir("password-login-off"), {"--password-login", "off", "--local-login-user", "admin"});
    createTestUsers(server, {"carol"});   // the administrator's login still works: it made her
    const HttpReply carol = passwordLogin(server, "carol", testPassword("carol"));
    EXPECT_EQ(carol.status, 403) << carol.body;
    EXPECT_EQ(carol.json()["error"]["code"], "password_login_off") << carol.body;
    // The same answer whether or not the name or the password is right: it tells nothing.
    const HttpReply wrong = passwordLogin(server, "carol", "not-her-password");
    EXPECT_EQ(wrong.status, 403);
    EXPECT_EQ(passwordLogin(server, "nobody-here", "whatever-it-is").status, 403);
    EXPECT_EQ(passwordLogin(server, "admin", "not-the-password").status, 401);
    EXPECT_EQ(passwordLogin(server, "admin", kAdminPassword).status, 200);
}

TEST(PasswordLoginOff, AServerThatWouldLetNobodyInRefusesToStart)
{
    tlmhub::server::ServerOptions options;
    std::string error, help;
    char program[] = "tlmhub-server", flag[] = "--password-login", off[] = "off";
    char* alone[] = {program, flag, off, nullptr};
    EXPECT_FALSE(tlmhub::server::parseServerOptions(3, alone, options, error, help));
    EXPECT_NE(error.find("--local-login-user"), std::string::npos) << error;

    char named[] = "--local-login-user", admin[] = "admin";
    char* withAdministrator[] = {program, flag, off, named, admin, nullptr};
    tlmhub::server::ServerOptions allowed;
    ASSERT_TRUE(tlmhub::server::parseServerOptions(5, withAdministrator, allowed, error, help)) << error;
    EXPECT_FALSE(allowed.passwordLogin);
    EXPECT_EQ(allowed.localLoginUsers, std::vector<std::string>{"admin"});
}

} // namespace tlmhub::test
