// Signing in with a directory's names and passwords (issue 43 item 2, docs/sign-in.md), against
// a real slapd started by the test on loopback with TLS: the person gets an account of their
// own (never a local one of the same name), roles follow groups, values are escaped, the
// certificate is verified, and a directory that cannot be asked leaves local logins working.
#include "ServerHarness.h"
#include "TemporarySlapd.h"

#include "server/auth/DirectorySignIn.h"
#include "server/auth/LdapDirectory.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using namespace tlmhub::test;
using tlmhub::server::accountNameFor;
using tlmhub::server::escapeDnValue;
using tlmhub::server::escapeFilterValue;
using tlmhub::server::withUsername;

namespace {

// People (passwords "<uid>-password" but the service account's), a teachers' group with bob,
// and names that need escaping in a DN ("doe, jane") and in a filter ("star*", beside
// "starlight", whom an unescaped filter would also find).
std::string ldapDirectoryLdif()
{
    std::string ldif = "dn: ou=people,dc=example,dc=org\nobjectClass: organizationalUnit\nou: people\n\n"
                       "dn: ou=groups,dc=example,dc=org\nobjectClass: organizationalUnit\nou: groups\n\n"
                       "dn: cn=reader,dc=example,dc=org\nobjectClass: organizationalRole\nobjectClass: simpleSecurityObject\n"
                       "cn: reader\nuserPassword: reader-secret\n\n";
    for (const std::string uid : {"alice", "bob", "admin", "star*", "starlight"})
        ldif += "dn: uid=" + escapeDnValue(uid) + ",ou=people,dc=example,dc=org\nobjectClass: inetOrgPerson\nuid: " + uid +
                "\ncn: " + uid + "\nsn: " + uid + "\nuserPassword: " + uid + "-password\n\n";
    ldif += "dn: uid=doe\\2C jane,ou=people,dc=example,dc=org\nobjectClass: inetOrgPerson\nuid: doe, jane\ncn: Jane Doe\n"
            "sn: Doe\nuserPassword: jane-password\n\n";
    ldif += "dn: cn=teachers,ou=groups,dc=example,dc=org\nobjectClass: groupOfNames\ncn: teachers\n"
            "member: uid=bob,ou=people,dc=example,dc=org\n\n";
    return ldif;
}

const std::string kLdapPeople = "ou=people,dc=example,dc=org";
const std::string kLdapTeachers = "cn=teachers,ou=groups,dc=example,dc=org";

HttpReply signInTo(const ServerProcess& server, const std::string& user, const std::string& password)
{
    HttpClient client(server.port());
    return client.post("/api/v1/auth/login", {{"username", user}, {"password", password}});
}

class LdapLogins : public ::testing::Test {
protected:
    static void SetUpTestSuite() { slapd = new TemporarySlapd(ldapDirectoryLdif()); }
    static void TearDownTestSuite()
    {
        delete slapd;
        slapd = nullptr;
    }
    static TemporarySlapd* slapd;

    // A server signing in by direct bind over ldaps:// with the test CA, bob's group mapped to teacher.
    std::unique_ptr<ServerProcess> bindingServer(const std::string& name, std::vector<std::string> more = {})
    {
        std::vector<std::string> args = {"--ldap-url", slapd->ldapsUrl(), "--ldap-bind-dn", "uid={username}," + kLdapPeople,
                                         "--ldap-ca-file", slapd->caFile().string(), "--ldap-role-group", "teacher=" + kLdapTeachers};
        args.insert(args.end(), more.begin(), more.end());
        return std::make_unique<ServerProcess>(freshTempDir(name), args);
    }
};
TemporarySlapd* LdapLogins::slapd = nullptr;

} // namespace

TEST(LdapEscaping, DnAndFilterValuesAreEscapedAsTheRfcsSay)
{
    EXPECT_EQ(escapeDnValue("doe, jane"), "doe\\, jane");
    EXPECT_EQ(escapeDnValue("a+b=c;d<e>\"f\\"), "a\\+b\\=c\\;d\\<e\\>\\\"f\\\\");
    EXPECT_EQ(escapeDnValue(" #lead"), "\\ #lead");
    EXPECT_EQ(escapeDnValue("#hash"), "\\#hash");
    EXPECT_EQ(escapeDnValue("trail "), "trail\\ ");
    EXPECT_EQ(escapeDnValue(std::string("nul\0x", 5)), "nul\\00x");
    EXPECT_EQ(escapeFilterValue("star*)(uid=*"), "star\\2a\\29\\28uid=\\2a");
    EXPECT_EQ(escapeFilterValue("back\\slash"), "back\\5cslash");
    EXPECT_EQ(escapeFilterValue(std::string("a\0b", 3)), "a\\00b");
    EXPECT_EQ(withUsername("(&(uid={username})(mail={username}))", "x\\2a"), "(&(uid=x\\2a)(mail=x\\2a))");
    EXPECT_EQ(accountNameFor("doe, jane"), "doe__jane");
    EXPECT_EQ(accountNameFor(""), "user");
    EXPECT_EQ(accountNameFor(std::string(80, 'a')).size(), 60u);
}

TEST_F(LdapLogins, APersonGetsTheirOwnAccountOnFirstSignInAndTheSameOneAfter)
{
    const auto server = bindingServer("ldap-bind");
    const HttpReply first = signInTo(*server, "alice", "alice-password");
    ASSERT_EQ(first.status, 200) << first.body << server->output();
    EXPECT_EQ(first.json()["user"]["username"], "alice");
    EXPECT_EQ(first.json()["user"]["role"], "user");
    // Typed in another case, the directory finds the same entry, and so the same account.
    const HttpReply again = signInTo(*server, "ALICE", "alice-password");
    ASSERT_EQ(again.status, 200) << again.body;
    EXPECT_EQ(again.json()["user"]["id"], first.json()["user"]["id"]);

    EXPECT_EQ(signInTo(*server, "alice", "wrong-password").status, 401);
    EXPECT_EQ(signInTo(*server, "alice", "").status, 400) << "an empty password would be an unauthenticated bind";
    EXPECT_EQ(signInTo(*server, "nobody-here", "x-password").status, 401);
    // The token works like a password login's.
    HttpClient alice(server->port());
    alice.setToken(first.json()["token"].get<std::string>());
    EXPECT_EQ(alice.get("/api/v1/auth/me").json()["username"], "alice");
}

TEST_F(LdapLogins, TheDirectoryNamesThePersonByTheirEntrysUuidAndNeverBindsWithoutAPassword)
{
    using tlmhub::server::LdapDirectory;
    using Outcome = tlmhub::server::LdapSignIn::Outcome;
    tlmhub::server::LdapSettings settings;
    settings.url = slapd->ldapsUrl();
    settings.bindDnTemplate = "uid={username}," + kLdapPeople;
    settings.caFile = slapd->caFile().string();
    settings.roleGroups = {{.role = "teacher", .groupDn = kLdapTeachers}};
    const LdapDirectory directory(settings);
    const auto bob = directory.signIn("BOB", "bob-password");
    ASSERT_EQ(bob.outcome, Outcome::SignedIn) << bob.message;
    EXPECT_EQ(bob.dn, "uid=bob," + kLdapPeople) << "as the directory stores it";
    EXPECT_TRUE(bob.subject.starts_with("entryUUID:")) << bob.subject;
    EXPECT_EQ(bob.groups, std::vector<std::string>{kLdapTeachers});
    EXPECT_TRUE(directory.signIn("alice", "alice-password").groups.empty());
    // An empty password would bind unauthenticated, which a directory accepts for anyone.
    EXPECT_EQ(directory.signIn("alice", "").outcome, Outcome::WrongCredentials);
    EXPECT_EQ(directory.signIn("", "x").outcome, Outcome::WrongCredentials);
    // A name that is a DN's syntax but no entry's.
    EXPECT_EQ(directory.signIn("alice,ou=elsewhere", "alice-password").outcome, Outcome::WrongCredentials);
}

TEST_F(LdapLogins, TheDirectorysAdminIsNotTheLocalAdministrator)
{
    const auto server = bindingServer("ldap-admin");
    const HttpReply directoryAdmin = signInTo(*server, "admin", "admin-password");
    ASSERT_EQ(directoryAdmin.status, 200) << directoryAdmin.body;
    EXPECT_EQ(directoryAdmin.json()["user"]["username"], "admin-2");
    EXPECT_EQ(directoryAdmin.json()["user"]["role"], "user");
    const HttpReply local = signInTo(*server, "admin", kAdminPassword);
    ASSERT_EQ(local.status, 200) << local.body;
    EXPECT_EQ(local.json()["user"]["role"], "admin");
    EXPECT_NE(local.json()["user"]["id"], directoryAdmin.json()["user"]["id"]);
}

TEST_F(LdapLogins, RolesFollowTheMappedGroups)
{
    const auto server = bindingServer("ldap-roles");
    const HttpReply bob = signInTo(*server, "bob", "bob-password");
    ASSERT_EQ(bob.status, 200) << bob.body;
    EXPECT_EQ(bob.json()["user"]["role"], "teacher");
    EXPECT_EQ(signInTo(*server, "alice", "alice-password").json()["user"]["role"], "user");
}

TEST_F(LdapLogins, SearchThenBindWithStartTlsEscapesTheNameInTheFilterAndTheDn)
{
    const std::filesystem::path secret = freshTempDir("ldap-secret") / "reader-password";
    std::ofstream(secret) << "reader-secret\n";
    std::filesystem::permissions(secret, std::filesystem::perms::owner_read | std::filesystem::perms::owner_write);
    ServerProcess server(freshTempDir("ldap-search"),
                         {"--ldap-url", slapd->startTlsUrl(), "--ldap-search-base", kLdapPeople, "--ldap-service-dn",
                          "cn=reader,dc=example,dc=org", "--ldap-service-password-file", secret.string(), "--ldap-ca-file",
                          slapd->caFile().string()});
    const HttpReply jane = signInTo(server, "doe, jane", "jane-password");
    ASSERT_EQ(jane.status, 200) << jane.body << server.output();
    EXPECT_EQ(jane.json()["user"]["username"], "doe__jane");
    // Unescaped, "(uid=star*)" would find star* and starlight, and nobody could sign in by it.
    const HttpReply star = signInTo(server, "star*", "star*-password");
    ASSERT_EQ(star.status, 200) << star.body;
    EXPECT_EQ(signInTo(server, "star*", "starlight-password").status, 401);
    EXPECT_EQ(signInTo(server, "*", "alice-password").status, 401);

    // Direct bind escapes the DN: "doe, jane" is one value, not uid=doe plus a stray RDN.
    const auto binding = bindingServer("ldap-bind-escaped");
    EXPECT_EQ(signInTo(*binding, "doe, jane", "jane-password").status, 200);
}

TEST_F(LdapLogins, AnUntrustedCertificateOrAnUnreachableDirectoryIsUnavailableAndLocalLoginsStillWork)
{
    ServerProcess untrusted(freshTempDir("ldap-untrusted"),
                            {"--ldap-url", slapd->ldapsUrl(), "--ldap-bind-dn", "uid={username}," + kLdapPeople,
                             "--ldap-ca-file", slapd->otherCaFile().string()});
    const HttpReply refused = signInTo(untrusted, "alice", "alice-password");
    EXPECT_EQ(refused.status, 503) << refused.body;
    EXPECT_EQ(refused.json()["error"]["code"], "directory_unavailable");
    EXPECT_FALSE(refused.headers.at("Retry-After").empty());
    EXPECT_EQ(signInTo(untrusted, "admin", kAdminPassword).status, 200);

    ServerProcess unreachable(freshTempDir("ldap-unreachable"),
                              {"--ldap-url", "ldaps://127.0.0.1:" + std::to_string(freeLoopbackPort()), "--ldap-bind-dn",
                               "uid={username}," + kLdapPeople, "--ldap-timeout", "2"});
    const HttpReply down = signInTo(unreachable, "alice", "alice-password");
    EXPECT_EQ(down.status, 503) << down.body;
    EXPECT_NE(down.json()["error"]["message"].get<std::string>().find("directory"), std::string::npos) << down.body;
    // Why is for the log: the directory's address is not told to whoever tries a login.
    EXPECT_EQ(down.body.find("127.0.0.1"), std::string::npos) << down.body;
    EXPECT_EQ(signInTo(unreachable, "admin", kAdminPassword).status, 200);
}

TEST_F(LdapLogins, DirectoryLoginsCountTowardsTheLoginLimitsAndNoAccountIsMadeWhenTurnedOff)
{
    const auto server = bindingServer("ldap-limits", {"--ldap-create-accounts", "off"});
    for (int i = 0; i < 5; ++i) EXPECT_EQ(signInTo(*server, "bob", "wrong-password").status, 401);
    const HttpReply limited = signInTo(*server, "bob", "bob-password");
    EXPECT_EQ(limited.status, 429) << limited.body;
    // Without account making, a person the directory vouches for gets a clear refusal.
    const HttpReply alice = signInTo(*server, "alice", "alice-password");
    EXPECT_EQ(alice.status, 403) << alice.body;
    EXPECT_EQ(alice.json()["error"]["code"], "no_account");
}

TEST_F(LdapLogins, WithPasswordLoginOffDirectoryPeopleSignInAndLocalPasswordsDoNot)
{
    const auto server = bindingServer("ldap-password-off", {"--password-login", "off", "--local-login-user", "admin"});
    createTestUsers(*server, {"carol"});
    EXPECT_EQ(signInTo(*server, "alice", "alice-password").status, 200) << "a directory password is not a local one";
    // carol is not in the directory, and her local password no longer logs her in.
    EXPECT_EQ(signInTo(*server, "carol", testPassword("carol")).status, 401);
    EXPECT_EQ(signInTo(*server, "admin", kAdminPassword).status, 200);
}
