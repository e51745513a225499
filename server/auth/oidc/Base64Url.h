#pragma once
// base64url without padding (RFC 4648 §5), the encoding of every part of a JSON Web Token,
// of the keys' numbers in a key set and of a PKCE challenge.
#include <optional>
#include <string>
#include <string_view>

namespace tlmhub::server {

std::string encodeBase64Url(std::string_view bytes);
// nullopt for text that is not base64url without padding.
std::optional<std::string> decodeBase64Url(std::string_view text);

} // namespace tlmhub::server
