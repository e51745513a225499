#pragma once
// fmi2Instantiate's resourceLocation: a URI, which for a local FMU is file:///dir or
// file:/dir, with reserved bytes percent-encoded.
#include <optional>
#include <string>

namespace tlmhub::fmu {

// The local directory a file URI names, without a trailing '/'; nullopt for other URIs
// (another scheme, a remote host, a broken escape).
std::optional<std::string> directoryOfFileUri(const std::string& uri);

} // namespace tlmhub::fmu
