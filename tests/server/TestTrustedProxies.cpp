// Which address the failed-login limits count (issue 37 M3): the peer's, unless the peer is
// a trusted proxy whose single, well-formed X-Forwarded-For names the client.
#include "server/http/TrustedProxies.h"

#include <gtest/gtest.h>

namespace tlmhub::server {
namespace {

TrustedProxies trustedRanges(std::initializer_list<const char*> ranges)
{
    TrustedProxies p;
    for (const char* r : ranges) EXPECT_TRUE(p.add(r)) << r;
    return p;
}

TEST(TrustedProxies, RangesAreAddressesWithAnOptionalPrefix)
{
    TrustedProxies p;
    for (const char* good : {"127.0.0.1", "10.0.0.0/8", "0.0.0.0/0", "::1", "2001:db8::/32", "fd00::/128"})
        EXPECT_TRUE(p.add(good)) << good;
    for (const char* bad : {"", "10.0.0.0/", "10.0.0.0/33", "::/129", "10.0.0.0/8x", "nginx", "10.0.0/8", "1.2.3.4/-1"})
        EXPECT_FALSE(p.add(bad)) << bad;
}

TEST(TrustedProxies, TheClientIsTheRightmostEntryOutsideTheTrustedRanges)
{
    const TrustedProxies p = trustedRanges({"10.0.0.0/8", "192.168.1.7"});
    // nginx at 10.0.0.2 appended what connected to it; the client's own claim is to the left.
    EXPECT_EQ(p.clientAddress("10.0.0.2", {"6.6.6.6, 203.0.113.5"}), "203.0.113.5");
    EXPECT_EQ(p.clientAddress("10.0.0.2", {"203.0.113.5, 192.168.1.7 ,10.1.2.3"}), "203.0.113.5");
    EXPECT_EQ(p.clientAddress("192.168.1.7", {"2001:db8::5"}), "2001:db8::5");
    // Every hop trusted: the first one is the client.
    EXPECT_EQ(p.clientAddress("10.0.0.2", {"10.9.9.9, 10.0.0.3"}), "10.9.9.9");
    // An IPv4 client written as IPv6 counts as IPv4, in the header and as the peer.
    EXPECT_EQ(p.clientAddress("::ffff:10.0.0.2", {"::ffff:203.0.113.9"}), "203.0.113.9");
}

TEST(TrustedProxies, AnyDoubtLeavesThePeer)
{
    const TrustedProxies p = trustedRanges({"10.0.0.0/8"});
    // A peer that is no trusted proxy: its header is the client's own say.
    EXPECT_EQ(p.clientAddress("203.0.113.5", {"10.0.0.1"}), "203.0.113.5");
    EXPECT_EQ(p.clientAddress("11.0.0.1", {"1.2.3.4"}), "11.0.0.1");
    // No header, a repeated one, a malformed entry anywhere.
    EXPECT_EQ(p.clientAddress("10.0.0.2", {}), "10.0.0.2");
    EXPECT_EQ(p.clientAddress("10.0.0.2", {"1.2.3.4", "5.6.7.8"}), "10.0.0.2");
    for (const char* malformed : {"", ",", "1.2.3.4,", "unknown, 1.2.3.4", "1.2.3.4:8080", "[::1]", "1.2.3.4 5.6.7.8"})
        EXPECT_EQ(p.clientAddress("10.0.0.2", {malformed}), "10.0.0.2") << malformed;
    // With no trusted proxy at all, nobody's header counts.
    EXPECT_EQ(TrustedProxies().clientAddress("10.0.0.2", {"1.2.3.4"}), "10.0.0.2");
}

} // namespace
} // namespace tlmhub::server
