#include "server/store/UserStore.h"

#include "server/auth/PasswordHasher.h"

#include <SQLiteCpp/Statement.h>

namespace tlmhub::server {

namespace {

User readUser(SQLite::Statement& q)
{
    User u;
    u.id = q.getColumn(0).getInt64();
    u.username = q.getColumn(1).getString();
    u.role = q.getColumn(2).getString();
    return u;
}

bool isUsernameChar(char c)
{
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') ||
           c == '_' || c == '.' || c == '-';
}

// Verified against when the user does not exist, so a miss costs as much as a wrong password.
const std::string& decoyHash()
{
    static const std::string hash = hashPassword("tlmhub decoy password");
    return hash;
}

} // namespace

bool isValidUsername(const std::string& username)
{
    if (username.empty() || username.size() > 64) return false;
    for (char c : username)
        if (!isUsernameChar(c)) return false;
    return true;
}

UserStore::UserStore(Database& db) : mDb(db)
{
    std::lock_guard lock(mDb.mutex());
    mDb.sql().exec(
        "CREATE TABLE IF NOT EXISTS users ("
        " id INTEGER PRIMARY KEY,"
        " username TEXT UNIQUE NOT NULL,"
        " password_hash TEXT,"
        " role TEXT CHECK(role IN ('admin','teacher','user')),"
        " created_at INTEGER)");
}

std::optional<User> UserStore::create(const std::string& username, const std::string& password,
                                      const std::string& role, std::string& error)
{
    if (!isValidUsername(username)) { error = kBadUsername; return std::nullopt; }
    if (!isValidRole(role)) { error = kBadRole; return std::nullopt; }
    if (password.size() < kMinPasswordLength) { error = kShortPassword; return std::nullopt; }
    if (findByName(username)) { error = kUsernameTaken; return std::nullopt; }

    const std::string hash = hashPassword(password);
    std::lock_guard lock(mDb.mutex());
    // INSERT OR IGNORE: a concurrent create of the same name loses here, not with an exception.
    SQLite::Statement insert(mDb.sql(),
                             "INSERT OR IGNORE INTO users(username, password_hash, role, created_at)"
                             " VALUES(?, ?, ?, ?)");
    insert.bind(1, username);
    insert.bind(2, hash);
    insert.bind(3, role);
    insert.bind(4, static_cast<std::int64_t>(unixNow()));
    if (insert.exec() == 0) { error = kUsernameTaken; return std::nullopt; }
    return User{mDb.sql().getLastInsertRowid(), username, role};
}

std::optional<std::string> UserStore::passwordHash(const std::string& username, std::int64_t& id)
{
    std::lock_guard lock(mDb.mutex());
    SQLite::Statement q(mDb.sql(), "SELECT id, password_hash FROM users WHERE username = ?");
    q.bind(1, username);
    if (!q.executeStep() || q.getColumn(1).isNull()) return std::nullopt;
    id = q.getColumn(0).getInt64();
    return q.getColumn(1).getString();
}

std::optional<User> UserStore::authenticate(const std::string& username,
                                            const std::string& password)
{
    std::int64_t id = 0;
    const std::optional<std::string> hash = passwordHash(username, id);
    if (!hash) {
        verifyPassword(decoyHash(), password);
        return std::nullopt;
    }
    if (!verifyPassword(*hash, password)) return std::nullopt;
    return find(id);
}

std::optional<User> UserStore::find(std::int64_t id)
{
    std::lock_guard lock(mDb.mutex());
    SQLite::Statement q(mDb.sql(), "SELECT id, username, role FROM users WHERE id = ?");
    q.bind(1, id);
    if (!q.executeStep()) return std::nullopt;
    return readUser(q);
}

std::optional<User> UserStore::findByName(const std::string& username)
{
    std::lock_guard lock(mDb.mutex());
    SQLite::Statement q(mDb.sql(), "SELECT id, username, role FROM users WHERE username = ?");
    q.bind(1, username);
    if (!q.executeStep()) return std::nullopt;
    return readUser(q);
}

std::vector<User> UserStore::list()
{
    std::lock_guard lock(mDb.mutex());
    SQLite::Statement q(mDb.sql(), "SELECT id, username, role FROM users ORDER BY id");
    std::vector<User> users;
    while (q.executeStep()) users.push_back(readUser(q));
    return users;
}

std::size_t UserStore::count()
{
    std::lock_guard lock(mDb.mutex());
    SQLite::Statement q(mDb.sql(), "SELECT COUNT(*) FROM users");
    q.executeStep();
    return static_cast<std::size_t>(q.getColumn(0).getInt64());
}

bool UserStore::changePassword(std::int64_t id, const std::string& oldPw,
                               const std::string& newPw, std::string& error)
{
    std::optional<std::string> oldHash;
    {
        std::lock_guard lock(mDb.mutex());
        SQLite::Statement q(mDb.sql(), "SELECT password_hash FROM users WHERE id = ?");
        q.bind(1, id);
        if (!q.executeStep()) { error = kNoSuchUser; return false; }
        if (!q.getColumn(0).isNull()) oldHash = q.getColumn(0).getString();
    }
    if (!oldHash || !verifyPassword(*oldHash, oldPw)) { error = kWrongPassword; return false; }
    if (newPw.size() < kMinPasswordLength) { error = kShortPassword; return false; }

    const std::string newHash = hashPassword(newPw);
    std::lock_guard lock(mDb.mutex());
    SQLite::Statement update(mDb.sql(), "UPDATE users SET password_hash = ? WHERE id = ?");
    update.bind(1, newHash);
    update.bind(2, id);
    if (update.exec() == 0) { error = kNoSuchUser; return false; }
    return true;
}

} // namespace tlmhub::server
