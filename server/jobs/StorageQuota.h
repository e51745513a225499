#pragma once
// How sizes read in messages, and the one message a user's full quota of stored results
// (--max-stored-bytes-per-user) gives, whichever request ran into it.
#include <cstddef>
#include <string>

namespace tlmhub::server {

// "512 bytes", "812.5 KiB", "2.41 MiB", "1.00 GiB": one formatter, so two sizes in a message
// compare as the numbers do.
std::string byteSize(std::size_t bytes);
// "your stored results use 2.41 MiB of 2.00 MiB (--max-stored-bytes-per-user); delete old
// jobs or studies first"
std::string quotaMessage(std::size_t stored, std::size_t quota);

} // namespace tlmhub::server
