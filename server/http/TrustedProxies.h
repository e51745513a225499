#pragma once
// Which address a request comes from when the server sits behind reverse proxies
// (--trusted-proxy CIDR, repeatable). Only a connection from a trusted proxy may name the
// client, in X-Forwarded-For; the client is the rightmost entry outside the trusted ranges
// (entries to its left are whatever the client sent). A missing, repeated or malformed
// header, or a peer that is no trusted proxy, leaves the peer's own address.
#include <boost/asio/ip/address.hpp>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tlmhub::server {

class TrustedProxies {
public:
    // Adds "10.0.0.0/8", "2001:db8::/32" or a single address; false when `cidr` is none.
    bool add(const std::string& cidr);
    bool empty() const { return mRanges.empty(); }

    // `forwardedFor`: the X-Forwarded-For fields of the request, in order (none, one, or
    // several when the header was repeated).
    std::string clientAddress(const std::string& peer, const std::vector<std::string_view>& forwardedFor) const;

private:
    struct Range {
        boost::asio::ip::address network;
        unsigned prefix;
    };
    bool trusted(const boost::asio::ip::address& address) const;

    std::vector<Range> mRanges;
};

} // namespace tlmhub::server
