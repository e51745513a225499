#include "server/app/Bootstrap.h"

#include "core/hmf/HmfLoader.h"
#include "server/auth/Sodium.h"
#include "server/store/UnixTime.h"

#include <sodium.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace tlmhub::server {

namespace fs = std::filesystem;

namespace {

std::string randomPassword(std::size_t length)
{
    // Letters and digits only, so the printed password survives copy and paste from a log.
    static constexpr char kAlphabet[] =
        "ABCDEFGHJKLMNPQRSTUVWXYZabcdefghijkmnopqrstuvwxyz23456789";
    ensureSodium();
    std::string password;
    for (std::size_t i = 0; i < length; ++i)
        password += kAlphabet[randombytes_uniform(sizeof kAlphabet - 1)];
    return password;
}

std::vector<fs::path> hmfFilesIn(const fs::path& dir, std::string& log)
{
    std::vector<fs::path> files;
    std::error_code ec;
    fs::directory_iterator it(dir, ec);
    if (ec) {
        log += "examples: cannot read directory " + dir.string() + ": " + ec.message() + "\n";
        return files;
    }
    for (const fs::directory_entry& entry : it)
        if (entry.is_regular_file() && entry.path().extension() == ".hmf")
            files.push_back(entry.path());
    std::sort(files.begin(), files.end(),
              [](const fs::path& a, const fs::path& b) { return a.filename() < b.filename(); });
    return files;
}

bool readFile(const fs::path& path, std::string& text)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) return false;
    std::ostringstream buffer;
    buffer << in.rdbuf();
    text = buffer.str();
    return static_cast<bool>(in) || in.eof();
}

} // namespace

std::optional<std::string> ensureAdmin(Accounts& users, const char* envPassword)
{
    if (users.findByName(kAdminUsername)) return std::nullopt;
    const bool chosen = envPassword != nullptr && envPassword[0] != '\0';
    const std::string password = chosen ? std::string(envPassword) : randomPassword(16);
    std::string error;
    if (!users.create(kAdminUsername, password, kRoleAdmin, error)) {
        // Another node starting on the same database at the same moment created it first.
        if (users.findByName(kAdminUsername)) return std::nullopt;
        throw std::runtime_error("cannot create the admin user: " + error);
    }
    if (chosen) return std::nullopt;
    return password;
}

int seedExamples(ModelStore& models, MetaStore& meta, Accounts& users,
                 const std::vector<std::string>& dirs, std::string& log)
{
    const std::optional<User> admin = users.findByName(kAdminUsername);
    if (!admin) {
        log += "examples: no admin user, nothing seeded\n";
        return 0;
    }
    int added = 0;
    for (const std::string& dir : dirs) {
        for (const fs::path& file : hmfFilesIn(dir, log)) {
            const std::string marker = "seeded:" + file.filename().string();
            if (meta.get(marker)) continue;
            std::string text;
            if (!readFile(file, text)) {
                log += "examples: cannot read " + file.string() + "\n";
                continue;
            }
            const LoadedModel loaded =
                loadHmfString(text, file.parent_path().string(), file.string());
            if (!loaded.root) {
                log += "examples: skipped " + file.string() + ": " + loaded.firstError() + "\n";
                continue;
            }
            // Marker first: of the API nodes starting together on one database, the one that
            // adds it seeds the file (a crash right after would leave that example out).
            if (!meta.insertIfAbsent(marker, std::to_string(unixNow()))) continue;
            models.create(admin->id, file.stem().string(), text, true);
            log += "examples: added " + file.stem().string() + "\n";
            ++added;
        }
    }
    return added;
}

} // namespace tlmhub::server
