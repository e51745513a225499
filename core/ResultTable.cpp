#include "core/ResultTable.h"

#include "core/LittleEndian.h"
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

void putDoubles(std::string& out, const std::vector<double>& values)
{
    littleEndian::put<std::uint64_t>(out, values.size());
    if constexpr (std::endian::native == std::endian::little) {
        out.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(double));
    } else {
        for (double v : values) littleEndian::put(out, std::bit_cast<std::uint64_t>(v));
    }
}

bool getDoubles(littleEndian::Reader& in, std::vector<double>& values)
{
    std::uint64_t n = 0;
    if (!in.get(n) || n > in.remaining() / sizeof(double)) return false;
    values.resize(n);
    if constexpr (std::endian::native == std::endian::little) {
        std::string_view bytes;
        in.take(n * sizeof(double), bytes);
        std::memcpy(values.data(), bytes.data(), bytes.size());
    } else {
        for (auto& v : values) {
            std::uint64_t raw = 0;
            in.get(raw);
            v = std::bit_cast<double>(raw);
        }
    }
    return true;
}

bool getMagic(littleEndian::Reader& in)
{
    std::string_view magic;
    return in.take(sizeof kMagic, magic) && std::memcmp(magic.data(), kMagic, sizeof kMagic) == 0;
}

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
    littleEndian::put(out, kVersion);
    putDoubles(out, time);
    littleEndian::put(out, static_cast<std::uint32_t>(columns.size()));
    for (const auto& c : columns) {
        littleEndian::putString(out, c.name);
        littleEndian::putString(out, c.unit);
        putDoubles(out, c.data);
    }
    return out;
}

bool ResultTable::deserialize(const std::string& bytes, ResultTable& out)
{
    littleEndian::Reader in(bytes);
    std::uint32_t version = 0, ncols = 0;
    ResultTable table;
    if (!getMagic(in) || !in.get(version) || version != kVersion) return false;
    if (!getDoubles(in, table.time) || !in.get(ncols)) return false;
    for (std::uint32_t i = 0; i < ncols; ++i) {
        ResultColumn c;
        if (!in.getString(c.name) || !in.getString(c.unit) || !getDoubles(in, c.data)) return false;
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
