#pragma once
// Unpacks a zip archive (an FMU) that may be hostile: bounded in entry count and in the bytes
// actually inflated (not what the archive claims), and every entry written as a new regular
// file or directory inside the destination, never through or as a link.
#include "core/Status.h"

#include <cstdint>
#include <filesystem>

namespace tlmhub::fmu {

struct ExtractionLimits {
    std::uint64_t maxTotalBytes = 1ull << 30;   // all entries inflated, bytes
    std::uint64_t maxFileBytes = 512ull << 20;  // one entry inflated, bytes
    std::uint64_t maxEntries = 10000;           // files and directories
};

// Extracts `archive` into `destination`, an existing empty directory. Refuses (InvalidModel,
// naming the entry) absolute names, "." or ".." components, backslashes, control characters,
// duplicate names, links and other special entries, and anything past a limit; IoError when
// the archive cannot be read or a file not written. What was extracted before a refusal
// stays: the caller removes the directory.
Status extractZip(const std::filesystem::path& archive, const std::filesystem::path& destination,
                  const ExtractionLimits& limits = {});

} // namespace tlmhub::fmu
