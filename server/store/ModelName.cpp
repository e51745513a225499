#include "server/store/ModelName.h"

namespace tlmhub::server {

namespace {

// Decodes one UTF-8 sequence at `i` (advancing it); -1 when malformed or overlong.
long nextCodePoint(const std::string& s, std::size_t& i)
{
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
    const unsigned char lead = byte(i);
    int length = lead < 0x80 ? 1 : (lead >> 5) == 0x6 ? 2 : (lead >> 4) == 0xe ? 3 : (lead >> 3) == 0x1e ? 4 : 0;
    if (length == 0 || i + length > s.size()) return -1;
    long cp = length == 1 ? lead : lead & (0x7f >> length);
    for (int k = 1; k < length; ++k) {
        if ((byte(i + k) & 0xc0) != 0x80) return -1;
        cp = (cp << 6) | (byte(i + k) & 0x3f);
    }
    static constexpr long kSmallest[] = {0, 0, 0x80, 0x800, 0x10000};
    if (cp < kSmallest[length] || cp > 0x10ffff || (cp >= 0xd800 && cp <= 0xdfff)) return -1;
    i += length;
    return cp;
}

bool isControl(long cp)
{
    return cp < 0x20 || (cp >= 0x7f && cp <= 0x9f) || cp == 0x2028 || cp == 0x2029;
}

bool isBidiControl(long cp)
{
    return cp == 0x061c || cp == 0x200e || cp == 0x200f || (cp >= 0x202a && cp <= 0x202e) ||
           (cp >= 0x2066 && cp <= 0x2069);
}

std::string hex(long cp)
{
    static constexpr char kDigits[] = "0123456789ABCDEF";
    std::string out = "U+";
    for (int shift = cp > 0xffff ? 20 : 12; shift >= 0; shift -= 4) out += kDigits[(cp >> shift) & 0xf];
    return out;
}

} // namespace

std::string modelNameProblem(const std::string& name)
{
    if (name.empty()) return "the name is empty";
    if (name.size() > kMaxModelNameBytes)
        return "the name is " + std::to_string(name.size()) + " bytes; at most " +
               std::to_string(kMaxModelNameBytes) + " are allowed";
    return nameCharacterProblem(name);
}

std::string nameCharacterProblem(const std::string& name)
{
    for (std::size_t i = 0; i < name.size();) {
        const std::size_t at = i;
        const long cp = nextCodePoint(name, i);
        if (cp < 0) return "the name is not valid UTF-8 (at byte " + std::to_string(at) + ")";
        if (isControl(cp)) return "the name contains the control character " + hex(cp);
        if (isBidiControl(cp)) return "the name contains the bidirectional control character " + hex(cp);
    }
    return {};
}

} // namespace tlmhub::server
