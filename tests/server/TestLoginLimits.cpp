// Failed-login limits (issue 37 M3): 50 logins with made-up names from one address locked the
// administrator out for a minute, and behind a reverse proxy or a lab's NAT every client
// shares one address. Failures now count per user name at an address (5 a minute) and per
// address (500 in 10 minutes); the address of a client behind a trusted proxy is taken from
// X-Forwarded-For (TestTrustedProxies.cpp has the header's rules).
#include "ServerHarness.h"

#include <gtest/gtest.h>

#include <string>

namespace tlmhub::test {
namespace {

HttpReply loginAttempt(HttpClient& client, const std::string& user, const std::string& password)
{
    return client.post("/api/v1/auth/login", {{"username", user}, {"password", password}});
}

HttpClient clientBehindProxy(const ServerProcess& server, const std::string& forwardedFor)
{
    HttpClient client(server.port());
    client.addHeader("X-Forwarded-For", forwardedFor);
    return client;
}

int retryAfterSeconds(const HttpReply& reply)
{
    const auto header = reply.headers.find("Retry-After");
    return header == reply.headers.end() ? -1 : std::stoi(header->second);
}

TEST(LoginLimits, MadeUpNamesFromOneAddressDoNotLockOutTheAdministrator)
{
    ServerProcess server(freshTempDir("login-names"));
    HttpClient attacker(server.port());
    for (int i = 0; i < 50; ++i) EXPECT_EQ(loginAttempt(attacker, "nobody" + std::to_string(i), "x").status, 401) << i;
    HttpClient admin(server.port());
    const auto reply = loginAttempt(admin, "admin", kAdminPassword);
    EXPECT_EQ(reply.status, 200) << reply.body;
}

TEST(LoginLimits, FiveFailuresLimitANameAtOneAddressOnly)
{
    ServerProcess server(freshTempDir("login-name-address"), {"--trusted-proxy", "127.0.0.1"});
    HttpClient guesser = clientBehindProxy(server, "203.0.113.1");
    for (int i = 0; i < 5; ++i) EXPECT_EQ(loginAttempt(guesser, "admin", "guess" + std::to_string(i)).status, 401) << i;
    const auto limited = loginAttempt(guesser, "admin", kAdminPassword);
    EXPECT_EQ(limited.status, 429) << limited.body;
    EXPECT_GE(retryAfterSeconds(limited), 1);
    EXPECT_LE(retryAfterSeconds(limited), 60);
    // The administrator elsewhere is not locked out by someone guessing their password.
    HttpClient owner = clientBehindProxy(server, "203.0.113.2");
    EXPECT_EQ(loginAttempt(owner, "admin", kAdminPassword).status, 200);
}

TEST(LoginLimits, PastTheAddressLimitOnlyCorrectPasswordsOfAccountsNotLimitedLogIn)
{
    ServerProcess server(freshTempDir("login-address"), {"--trusted-proxy", "127.0.0.1/32"});
    HttpClient nat = clientBehindProxy(server, "198.51.100.7");
    // 500 failures, each for a different name: no name reaches its own limit.
    for (int i = 0; i < 500; ++i) ASSERT_EQ(loginAttempt(nat, "student" + std::to_string(i), "wrong").status, 401) << i;
    const auto wrong = loginAttempt(nat, "admin", "wrong");
    EXPECT_EQ(wrong.status, 429) << wrong.body;
    EXPECT_GE(retryAfterSeconds(wrong), 1);
    EXPECT_LE(retryAfterSeconds(wrong), 600);
    EXPECT_EQ(loginAttempt(nat, "admin", kAdminPassword).status, 200);
    // Another address is not limited.
    HttpClient other = clientBehindProxy(server, "198.51.100.8");
    EXPECT_EQ(loginAttempt(other, "admin", "wrong").status, 401);
}

TEST(LoginLimits, WithoutATrustedProxyTheHeaderIsTheClientsOwnSay)
{
    ServerProcess server(freshTempDir("login-untrusted"));
    for (int i = 0; i < 5; ++i) {
        HttpClient client = clientBehindProxy(server, "203.0.113." + std::to_string(i));
        EXPECT_EQ(loginAttempt(client, "admin", "guess").status, 401) << i;
    }
    HttpClient next = clientBehindProxy(server, "203.0.113.99");
    EXPECT_EQ(loginAttempt(next, "admin", kAdminPassword).status, 429);
}

} // namespace
} // namespace tlmhub::test
