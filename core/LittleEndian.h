#pragma once
// Little-endian binary fields of stored results (ResultTable::serialize and the server's
// compressed form): unsigned integers and length-prefixed strings appended to a string, and
// read back with every length checked against what is left.
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace tlmhub::littleEndian {

template <std::unsigned_integral T>
void put(std::string& out, T value)
{
    for (std::size_t i = 0; i < sizeof(T); ++i) out.push_back(static_cast<char>((value >> (8 * i)) & 0xFF));
}

// A u32 length, then the bytes.
inline void putString(std::string& out, std::string_view s)
{
    put(out, static_cast<std::uint32_t>(s.size()));
    out.append(s);
}

class Reader {
public:
    explicit Reader(std::string_view bytes) : mBytes(bytes) {}

    template <std::unsigned_integral T>
    bool get(T& value)
    {
        if (mBytes.size() - mPos < sizeof(T)) return false;
        T v = 0;
        for (std::size_t i = 0; i < sizeof(T); ++i)
            v |= static_cast<T>(static_cast<unsigned char>(mBytes[mPos + i])) << (8 * i);
        mPos += sizeof(T);
        value = v;
        return true;
    }

    bool getString(std::string& s)
    {
        std::uint32_t n = 0;
        std::string_view bytes;
        if (!get(n) || !take(n, bytes)) return false;
        s.assign(bytes);
        return true;
    }

    // The next `n` bytes as they are.
    bool take(std::size_t n, std::string_view& bytes)
    {
        if (mBytes.size() - mPos < n) return false;
        bytes = mBytes.substr(mPos, n);
        mPos += n;
        return true;
    }

    std::size_t remaining() const { return mBytes.size() - mPos; }
    bool atEnd() const { return mPos == mBytes.size(); }

private:
    std::string_view mBytes;
    std::size_t mPos = 0;
};

} // namespace tlmhub::littleEndian
