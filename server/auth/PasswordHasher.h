#pragma once
// Password hashing with argon2id (libsodium), INTERACTIVE limits: about 64 MiB and 0.1 s per
// hash, which is what makes offline guessing expensive. The result is a self-describing
// "$argon2id$..." string holding salt and costs, so the limits can change later without
// invalidating stored hashes.
#include <string>

namespace tlmhub::server {

// The costs of new hashes, process-wide. Minimal (libsodium's least: one pass, 8 KiB) is for
// the fuzz targets, where a 0.1 s hash per input would stall the fuzzer, and for test servers
// (--password-hash-cost minimal), where every login would cost a tenth of a second of CPU.
// Verifying reads the costs from the stored hash, so either setting verifies every hash.
enum class PasswordCost { Interactive, Minimal };
void setPasswordCost(PasswordCost cost);

// Throws std::runtime_error when libsodium cannot allocate the memory the hash needs.
std::string hashPassword(const std::string& password);

// False for a wrong password and for a hash string that is not a valid argon2 hash.
bool verifyPassword(const std::string& hash, const std::string& password);

} // namespace tlmhub::server
