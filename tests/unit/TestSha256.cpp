// SHA-256 against the FIPS 180-2 example messages, fed whole and in uneven pieces.
#include "core/Sha256.h"

#include <gtest/gtest.h>

#include <string>

using tlmhub::Sha256;

namespace {

std::string digestInPieces(const std::string& message, std::size_t pieceSize)
{
    Sha256 hash;
    for (std::size_t i = 0; i < message.size(); i += pieceSize)
        hash.update(std::string_view(message).substr(i, pieceSize));
    return hash.hexDigest();
}

} // namespace

TEST(Sha256, EmptyMessage)
{
    EXPECT_EQ(Sha256().hexDigest(), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
}

TEST(Sha256, StandardExamples)
{
    EXPECT_EQ(digestInPieces("abc", 3), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
    // 56 bytes: the padding needs a second block.
    const std::string twoBlocks = "abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq";
    EXPECT_EQ(digestInPieces(twoBlocks, twoBlocks.size()),
              "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
}

TEST(Sha256, PiecesOfAnySizeGiveTheSameDigest)
{
    const std::string million(1000000, 'a');
    const std::string expected = "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0";
    for (std::size_t piece : {1000000u, 64u, 63u, 65u, 7u, 4096u})
        EXPECT_EQ(digestInPieces(million, piece), expected) << "pieces of " << piece;
}
