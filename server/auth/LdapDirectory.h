#pragma once
// Signing in against a university's LDAP directory (docs/sign-in.md): who a user name and
// password are there, and which of the configured groups they are in. Speaks LDAP through
// OpenLDAP's libldap; knows nothing of our accounts (DirectorySignIn links them).
//
// Secure by construction: TLS always (ldaps://, or StartTLS on ldap://) with the server's
// certificate verified; no anonymous or empty-password bind; every value put into a DN or a
// search filter escaped; every operation bounded in time.
#include <chrono>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tlmhub::server {

struct LdapSettings {
    std::string url;              // ldaps://host[:port] or ldap://host[:port] (StartTLS)
    // Direct bind: the user's DN with {username} in it, e.g. uid={username},ou=people,dc=uni,dc=edu.
    std::string bindDnTemplate;
    // Search then bind (when there is no template): under `searchBase`, the one entry that
    // `searchFilter` ({username} in it) finds, searched as the service account.
    std::string searchBase;
    std::string searchFilter = "(uid={username})";
    std::string serviceDn;
    std::string servicePassword;   // read from --ldap-service-password-file, never logged
    std::string caFile;            // CAs that sign the directory's certificate; empty: the system's
    struct RoleGroup {
        std::string role;          // admin, teacher or user
        std::string groupDn;       // a groupOfNames (or groupOfUniqueNames) entry
    };
    std::vector<RoleGroup> roleGroups;
    std::chrono::milliseconds timeout{5000};   // per connection and per operation
};

// RFC 4514: a value put into a DN (",+\"\\<>;=" and a leading space or '#', a trailing space, NUL).
std::string escapeDnValue(std::string_view value);
// RFC 4515: a value put into a search filter ("*()\\" and NUL as \hh).
std::string escapeFilterValue(std::string_view value);
// `pattern` with every {username} replaced by `escaped`.
std::string withUsername(std::string_view pattern, std::string_view escaped);

struct LdapSignIn {
    enum class Outcome {
        SignedIn,             // dn set; groups: the role groups (by their DN) the entry is a member of
        WrongCredentials,     // no such entry, more than one, or a wrong password
        Unavailable,          // the directory cannot be asked (message says why; logged)
    } outcome = Outcome::WrongCredentials;
    std::string dn;
    // Who they are for good: "entryUUID:…" when the directory keeps one, else "dn:" and the DN
    // as stored (a rename then makes a new account).
    std::string subject;
    std::vector<std::string> groups;
    std::string message;
};

class LdapDirectory {
public:
    explicit LdapDirectory(LdapSettings settings);
    const LdapSettings& settings() const { return mSettings; }

    // Blocks for the directory (up to a few timeouts): call it off the I/O threads.
    LdapSignIn signIn(const std::string& username, const std::string& password) const;

private:
    LdapSettings mSettings;
};

} // namespace tlmhub::server
