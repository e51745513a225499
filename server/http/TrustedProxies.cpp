#include "server/http/TrustedProxies.h"

#include <algorithm>
#include <charconv>

namespace tlmhub::server {

namespace ip = boost::asio::ip;

namespace {

// An IPv4 client seen through an IPv6 socket counts as IPv4.
ip::address unmapped(const ip::address& address)
{
    if (address.is_v6() && address.to_v6().is_v4_mapped())
        return ip::make_address_v4(ip::v4_mapped, address.to_v6());
    return address;
}

std::optional<ip::address> parseAddress(std::string_view text)
{
    boost::system::error_code ec;
    const ip::address address = ip::make_address(std::string(text), ec);
    if (ec) return std::nullopt;
    return unmapped(address);
}

std::string_view trimmed(std::string_view text)
{
    const auto first = text.find_first_not_of(" \t");
    if (first == std::string_view::npos) return {};
    const auto last = text.find_last_not_of(" \t");
    return text.substr(first, last - first + 1);
}

// The first `prefix` bits of two addresses of one family are equal.
template <typename Bytes>
bool samePrefix(const Bytes& a, const Bytes& b, unsigned prefix)
{
    for (std::size_t i = 0; i < a.size() && 8 * i < prefix; ++i) {
        const unsigned bits = std::min(8u, prefix - static_cast<unsigned>(8 * i));
        const auto mask = static_cast<unsigned char>(0xFF << (8 - bits));
        if ((a[i] ^ b[i]) & mask) return false;
    }
    return true;
}

} // namespace

bool TrustedProxies::add(const std::string& cidr)
{
    const auto slash = cidr.find('/');
    const auto address = parseAddress(std::string_view(cidr).substr(0, slash));
    if (!address) return false;
    const unsigned bits = address->is_v4() ? 32 : 128;
    unsigned prefix = bits;
    if (slash != std::string::npos) {
        const char* begin = cidr.data() + slash + 1;
        const char* end = cidr.data() + cidr.size();
        const auto [ptr, ec] = std::from_chars(begin, end, prefix);
        if (ec != std::errc() || ptr != end || begin == end || prefix > bits) return false;
    }
    mRanges.push_back({*address, prefix});
    return true;
}

bool TrustedProxies::trusted(const ip::address& address) const
{
    for (const Range& range : mRanges) {
        if (range.network.is_v4() != address.is_v4()) continue;
        const bool inside = address.is_v4()
                                ? samePrefix(range.network.to_v4().to_bytes(), address.to_v4().to_bytes(), range.prefix)
                                : samePrefix(range.network.to_v6().to_bytes(), address.to_v6().to_bytes(), range.prefix);
        if (inside) return true;
    }
    return false;
}

std::string TrustedProxies::clientAddress(const std::string& peer,
                                          const std::vector<std::string_view>& forwardedFor) const
{
    const auto peerAddress = parseAddress(peer);
    if (!peerAddress || !trusted(*peerAddress) || forwardedFor.size() != 1) return peer;
    // Right to left: each trusted proxy appended the address it was connected from.
    std::vector<ip::address> hops;
    std::string_view rest = forwardedFor.front();
    while (true) {
        const auto comma = rest.find(',');
        const auto entry = parseAddress(trimmed(rest.substr(0, comma)));
        if (!entry) return peer;
        hops.push_back(*entry);
        if (comma == std::string_view::npos) break;
        rest.remove_prefix(comma + 1);
    }
    for (auto hop = hops.rbegin(); hop != hops.rend(); ++hop)
        if (!trusted(*hop)) return hop->to_string();
    // Every hop is a trusted proxy: the first one is the client.
    return hops.front().to_string();
}

} // namespace tlmhub::server
