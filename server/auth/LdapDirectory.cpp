#include "server/auth/LdapDirectory.h"

#include <ldap.h>

#include <cstdio>
#include <sys/time.h>

namespace tlmhub::server {

std::string escapeDnValue(std::string_view value)
{
    std::string out;
    for (std::size_t i = 0; i < value.size(); ++i) {
        const char c = value[i];
        if (c == '\0') {
            out += "\\00";
            continue;
        }
        const bool special = c == ',' || c == '+' || c == '"' || c == '\\' || c == '<' || c == '>' || c == ';' || c == '=';
        const bool edge = (i == 0 && (c == ' ' || c == '#')) || (i + 1 == value.size() && c == ' ');
        if (special || edge) out += '\\';
        out += c;
    }
    return out;
}

std::string escapeFilterValue(std::string_view value)
{
    std::string out;
    for (const char c : value) {
        if (c == '*' || c == '(' || c == ')' || c == '\\' || c == '\0') {
            char hex[4];
            std::snprintf(hex, sizeof hex, "\\%02x", static_cast<unsigned char>(c));
            out += hex;
        } else {
            out += c;
        }
    }
    return out;
}

std::string withUsername(std::string_view pattern, std::string_view escaped)
{
    constexpr std::string_view kPlaceholder = "{username}";
    std::string out;
    for (std::size_t at = 0;;) {
        const std::size_t found = pattern.find(kPlaceholder, at);
        out += pattern.substr(at, found == std::string_view::npos ? std::string_view::npos : found - at);
        if (found == std::string_view::npos) return out;
        out += escaped;
        at = found + kPlaceholder.size();
    }
}

namespace {

// One connection to the directory, unbound (closed) when it goes.
class Connection {
public:
    Connection() = default;
    Connection(const Connection&) = delete;
    Connection& operator=(const Connection&) = delete;
    ~Connection()
    {
        if (mLd) ldap_unbind_ext_s(mLd, nullptr, nullptr);
    }
    LDAP* get() const { return mLd; }
    LDAP** out() { return &mLd; }

    // The server's own words on the last failure (a TLS error, a bad DN), if it gave any.
    std::string diagnostic() const
    {
        char* text = nullptr;
        ldap_get_option(mLd, LDAP_OPT_DIAGNOSTIC_MESSAGE, &text);
        std::string out = text ? text : "";
        if (text) ldap_memfree(text);
        return out;
    }

private:
    LDAP* mLd = nullptr;
};

timeval timevalOf(std::chrono::milliseconds ms)
{
    return {.tv_sec = static_cast<time_t>(ms.count() / 1000), .tv_usec = static_cast<suseconds_t>((ms.count() % 1000) * 1000)};
}

std::string failure(const Connection& c, const std::string& what, int code)
{
    std::string detail = c.get() ? c.diagnostic() : std::string();
    if (detail == "(unknown error code)") detail.clear();
    // libldap says no more when TLS fails than when nothing answers.
    if (code == LDAP_SERVER_DOWN || code == LDAP_CONNECT_ERROR)
        detail = "unreachable, or its certificate is not trusted (--ldap-ca-file)";
    return what + ": " + ldap_err2string(code) + (detail.empty() ? "" : " (" + detail + ")");
}

// Connected with TLS verified, or the reason it is not.
std::string open(const LdapSettings& s, Connection& c)
{
    int rc = ldap_initialize(c.out(), s.url.c_str());
    if (rc != LDAP_SUCCESS) return failure(c, "the LDAP URL " + s.url + " cannot be used", rc);
    int version = LDAP_VERSION3;
    ldap_set_option(c.get(), LDAP_OPT_PROTOCOL_VERSION, &version);
    ldap_set_option(c.get(), LDAP_OPT_REFERRALS, LDAP_OPT_OFF);
    const timeval limit = timevalOf(s.timeout);
    ldap_set_option(c.get(), LDAP_OPT_NETWORK_TIMEOUT, &limit);
    ldap_set_option(c.get(), LDAP_OPT_TIMEOUT, &limit);
    int demand = LDAP_OPT_X_TLS_DEMAND;
    ldap_set_option(c.get(), LDAP_OPT_X_TLS_REQUIRE_CERT, &demand);
    if (!s.caFile.empty()) ldap_set_option(c.get(), LDAP_OPT_X_TLS_CACERTFILE, s.caFile.c_str());
    // The options above are this connection's own only once it has a TLS context of its own.
    int client = 0;
    ldap_set_option(c.get(), LDAP_OPT_X_TLS_NEWCTX, &client);
    if (s.url.rfind("ldaps://", 0) == 0) return "";
    rc = ldap_start_tls_s(c.get(), nullptr, nullptr);
    return rc == LDAP_SUCCESS ? "" : failure(c, "StartTLS with " + s.url + " failed", rc);
}

int simpleBind(const Connection& c, const std::string& dn, const std::string& password)
{
    berval credentials{.bv_len = password.size(), .bv_val = const_cast<char*>(password.data())};
    return ldap_sasl_bind_s(c.get(), dn.c_str(), LDAP_SASL_SIMPLE, &credentials, nullptr, nullptr, nullptr);
}

// A bind refused for who or what was given, not for the directory's trouble.
bool refusedCredentials(int rc)
{
    return rc == LDAP_INVALID_CREDENTIALS || rc == LDAP_INVALID_DN_SYNTAX || rc == LDAP_NO_SUCH_OBJECT
           || rc == LDAP_UNWILLING_TO_PERFORM || rc == LDAP_INAPPROPRIATE_AUTH;
}

bool isMember(const Connection& c, const std::string& groupDn, const std::string& dn)
{
    berval value{.bv_len = dn.size(), .bv_val = const_cast<char*>(dn.data())};
    for (const char* attribute : {"member", "uniqueMember"})
        if (ldap_compare_ext_s(c.get(), groupDn.c_str(), attribute, &value, nullptr, nullptr) == LDAP_COMPARE_TRUE)
            return true;
    return false;
}

struct Entry {
    std::string dn;     // as the directory stores it
    std::string uuid;   // its entryUUID (RFC 4530), if the directory keeps one
};

// The one entry a search finds: empty when none or more than one; nullopt with `error` when
// the directory cannot be searched.
std::optional<Entry> findEntry(const LdapSettings& s, const Connection& c, const std::string& base, int scope,
                               const std::string& filter, std::string& error)
{
    char uuidAttribute[] = "entryUUID";
    char* attributes[] = {uuidAttribute, nullptr};
    timeval limit = timevalOf(s.timeout);
    LDAPMessage* result = nullptr;
    // At most two entries: two mean the name is ambiguous, and nobody signs in by it.
    const int rc = ldap_search_ext_s(c.get(), base.c_str(), scope, filter.c_str(), attributes, 0, nullptr, nullptr,
                                     &limit, 2, &result);
    Entry entry;
    if (rc == LDAP_SUCCESS && ldap_count_entries(c.get(), result) == 1) {
        LDAPMessage* found = ldap_first_entry(c.get(), result);
        char* dn = ldap_get_dn(c.get(), found);
        if (dn) entry.dn = dn;
        ldap_memfree(dn);
        berval** uuid = ldap_get_values_len(c.get(), found, "entryUUID");
        if (uuid && uuid[0]) entry.uuid.assign(uuid[0]->bv_val, uuid[0]->bv_len);
        ldap_value_free_len(uuid);
    }
    if (result) ldap_msgfree(result);
    if (rc != LDAP_SUCCESS && rc != LDAP_SIZELIMIT_EXCEEDED && rc != LDAP_NO_SUCH_OBJECT) {
        error = failure(c, "searching " + base + " failed", rc);
        return std::nullopt;
    }
    return entry;
}

} // namespace

LdapDirectory::LdapDirectory(LdapSettings settings) : mSettings(std::move(settings)) {}

LdapSignIn LdapDirectory::signIn(const std::string& username, const std::string& password) const
{
    using Outcome = LdapSignIn::Outcome;
    const auto unavailable = [](std::string message) {
        return LdapSignIn{.outcome = Outcome::Unavailable, .dn = {}, .subject = {}, .groups = {}, .message = std::move(message)};
    };
    // An empty password would be an unauthenticated bind, which succeeds for anyone.
    if (username.empty() || password.empty() || username.size() > 256) return {};
    Connection c;
    if (const std::string error = open(mSettings, c); !error.empty()) return unavailable(error);

    Entry entry;
    std::string error;
    if (!mSettings.bindDnTemplate.empty()) {
        entry.dn = withUsername(mSettings.bindDnTemplate, escapeDnValue(username));
    } else {
        if (const int rc = simpleBind(c, mSettings.serviceDn, mSettings.servicePassword); rc != LDAP_SUCCESS)
            return unavailable(failure(c, "the service account " + mSettings.serviceDn + " cannot bind", rc));
        const auto found = findEntry(mSettings, c, mSettings.searchBase, LDAP_SCOPE_SUBTREE,
                                     withUsername(mSettings.searchFilter, escapeFilterValue(username)), error);
        if (!found) return unavailable(error);
        if (found->dn.empty()) return {};
        entry = *found;
    }
    const int rc = simpleBind(c, entry.dn, password);
    if (refusedCredentials(rc)) return {};
    if (rc != LDAP_SUCCESS) return unavailable(failure(c, "binding to " + mSettings.url + " failed", rc));
    if (entry.uuid.empty()) {
        // The entry as stored: "uid=ALICE" typed and "uid=alice" stored are one person.
        const auto own = findEntry(mSettings, c, entry.dn, LDAP_SCOPE_BASE, "(objectClass=*)", error);
        if (!own) return unavailable(error);
        if (!own->dn.empty()) entry = *own;
    }

    LdapSignIn signedIn{.outcome = Outcome::SignedIn,
                        .dn = entry.dn,
                        .subject = entry.uuid.empty() ? "dn:" + entry.dn : "entryUUID:" + entry.uuid,
                        .groups = {},
                        .message = {}};
    // As the person themselves: a directory lets its members read their own groups.
    for (const LdapSettings::RoleGroup& group : mSettings.roleGroups)
        if (isMember(c, group.groupDn, entry.dn)) signedIn.groups.push_back(group.groupDn);
    return signedIn;
}

} // namespace tlmhub::server
