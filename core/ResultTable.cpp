#include "core/ResultTable.h"

#include "core/ResultView.h"
#include "core/System.h"

#include <bit>
#include <charconv>
#include <cstdint>
#include <cstring>

namespace tlmhub {

namespace {

// Serialized layout (version 1), all integers and doubles little-endian:
//   "TLRT" u32 version | u64 n, n doubles (time) | u32 columns |
//   per column: u32 len, name | u32 len, unit | u64 n, n doubles
constexpr char kMagic[4] = {'T', 'L', 'R', 'T'};
constexpr std::uint32_t kVersion = 1;

template <typename T>
void putLittleEndian(std::string& out, T value)
{
    for (std::size_t i = 0; i < sizeof(T); ++i)
        out.push_back(static_cast<char>((value >> (8 * i)) & 0xFF));
}

void putDoubles(std::string& out, const std::vector<double>& values)
{
    putLittleEndian<std::uint64_t>(out, values.size());
    if constexpr (std::endian::native == std::endian::little) {
        out.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(double));
    } else {
        for (double v : values) putLittleEndian(out, std::bit_cast<std::uint64_t>(v));
    }
}

void putString(std::string& out, const std::string& s)
{
    putLittleEndian<std::uint32_t>(out, static_cast<std::uint32_t>(s.size()));
    out += s;
}

class Reader {
public:
    explicit Reader(const std::string& bytes) : mBytes(bytes) {}

    template <typename T>
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

    bool getDoubles(std::vector<double>& values)
    {
        std::uint64_t n = 0;
        if (!get(n) || n > (mBytes.size() - mPos) / sizeof(double)) return false;
        values.resize(n);
        if constexpr (std::endian::native == std::endian::little) {
            std::memcpy(values.data(), mBytes.data() + mPos, n * sizeof(double));
            mPos += n * sizeof(double);
        } else {
            for (auto& v : values) {
                std::uint64_t raw = 0;
                get(raw);
                v = std::bit_cast<double>(raw);
            }
        }
        return true;
    }

    bool getString(std::string& s)
    {
        std::uint32_t n = 0;
        if (!get(n) || n > mBytes.size() - mPos) return false;
        s.assign(mBytes, mPos, n);
        mPos += n;
        return true;
    }

    bool getMagic()
    {
        if (mBytes.size() < sizeof kMagic || std::memcmp(mBytes.data(), kMagic, sizeof kMagic) != 0)
            return false;
        mPos = sizeof kMagic;
        return true;
    }

    bool atEnd() const { return mPos == mBytes.size(); }

private:
    const std::string& mBytes;
    std::size_t mPos = 0;
};

// "%.17g" (std::to_chars with general format and a precision is specified as printf's %g).
void appendNumber(std::string& out, double v)
{
    char buf[40];
    const auto res = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, 17);
    out.append(buf, res.ptr);
}

std::vector<const ResultColumn*> select(const ResultTable& table,
                                        const std::vector<std::string>& variables)
{
    std::vector<const ResultColumn*> out;
    if (variables.empty()) {
        for (const auto& c : table.columns) out.push_back(&c);
    } else {
        for (const auto& name : variables)
            if (const ResultColumn* c = table.column(name)) out.push_back(c);
    }
    return out;
}

} // namespace

ResultTable ResultTable::fromView(const ResultView& view)
{
    ResultTable table;
    const auto time = view.time();
    table.time.assign(time.begin(), time.end());
    table.columns.reserve(view.numVariables());
    std::vector<std::size_t> indices;
    std::vector<double*> out;
    for (std::size_t i = 0; i < view.numVariables(); ++i) {
        table.columns.push_back({view.variable(i).fullName, view.variable(i).unit,
                                 std::vector<double>(view.count(i))});
        indices.push_back(i);
    }
    for (auto& c : table.columns) out.push_back(c.data.data());
    view.copyData(indices, out);
    return table;
}

ResultTable ResultTable::fromSystem(const System& root) { return fromView(ResultView(root)); }

std::string ResultTable::toCsv(const std::vector<std::string>& variables) const
{
    std::string out;
    writeCsv([&out](std::string_view piece) { out += piece; }, variables);
    return out;
}

void ResultTable::writeCsv(const std::function<void(std::string_view)>& sink,
                           const std::vector<std::string>& variables) const
{
    constexpr std::size_t kPieceBytes = 64 * 1024;
    const std::vector<const ResultColumn*> cols = select(*this, variables);
    std::string piece = "time";
    for (const ResultColumn* c : cols) {
        piece += ',';
        piece += c->name;
    }
    piece += '\n';
    piece.reserve(kPieceBytes + 64);
    for (std::size_t r = 0; r < time.size(); ++r) {
        appendNumber(piece, time[r]);
        for (const ResultColumn* c : cols) {
            piece += ',';
            if (r < c->data.size()) appendNumber(piece, c->data[r]);
            if (piece.size() >= kPieceBytes) {
                sink(piece);
                piece.clear();
            }
        }
        piece += '\n';
    }
    if (!piece.empty()) sink(piece);
}

nlohmann::json ResultTable::toJson(const std::vector<std::string>& variables) const
{
    nlohmann::json vars = nlohmann::json::array();
    for (const ResultColumn* c : select(*this, variables))
        vars.push_back({{"name", c->name}, {"unit", c->unit}, {"data", c->data}});
    return {{"time", time}, {"variables", std::move(vars)}};
}

std::string ResultTable::serialize() const
{
    std::string out;
    out.reserve(byteSize());
    out.append(kMagic, sizeof kMagic);
    putLittleEndian(out, kVersion);
    putDoubles(out, time);
    putLittleEndian<std::uint32_t>(out, static_cast<std::uint32_t>(columns.size()));
    for (const auto& c : columns) {
        putString(out, c.name);
        putString(out, c.unit);
        putDoubles(out, c.data);
    }
    return out;
}

bool ResultTable::deserialize(const std::string& bytes, ResultTable& out)
{
    Reader in(bytes);
    std::uint32_t version = 0, ncols = 0;
    ResultTable table;
    if (!in.getMagic() || !in.get(version) || version != kVersion) return false;
    if (!in.getDoubles(table.time) || !in.get(ncols)) return false;
    for (std::uint32_t i = 0; i < ncols; ++i) {
        ResultColumn c;
        if (!in.getString(c.name) || !in.getString(c.unit) || !in.getDoubles(c.data)) return false;
        table.columns.push_back(std::move(c));
    }
    if (!in.atEnd()) return false;
    out = std::move(table);
    return true;
}

std::size_t ResultTable::byteSize() const
{
    std::size_t n = sizeof kMagic + 4 + 8 + time.size() * sizeof(double) + 4;
    for (const auto& c : columns) n += 4 + c.name.size() + 4 + c.unit.size() + 8 + c.data.size() * sizeof(double);
    return n;
}

bool ResultTable::hasColumn(const std::string& name) const { return column(name) != nullptr; }

const ResultColumn* ResultTable::column(const std::string& name) const
{
    for (const auto& c : columns)
        if (c.name == name) return &c;
    return nullptr;
}

} // namespace tlmhub
