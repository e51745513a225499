#include "server/store/ResultBlob.h"

#include "core/LittleEndian.h"

#include <zstd.h>

#include <bit>
#include <cstdint>
#include <cstring>
#include <map>
#include <memory>
#include <tuple>
#include <stdexcept>

namespace tlmhub::server {

namespace {

static_assert(std::endian::native == std::endian::little, "columns are shuffled from memory as they lie");

constexpr char kMagic[4] = {'T', 'L', 'R', 'T'};
constexpr std::uint32_t kVersion = 2;
// A lab's results are stored as fast as they are made. On shuffled columns the first fast
// level is as small as level 1 and a fifth quicker (bench/ServerBenchmark: Position Servo
// 528 kB either way, 1.9 ms against 2.4 ms).
constexpr int kCompressionLevel = -1;
// A column never holds more (the result limit is far below); a damaged blob that claims more
// is refused before anything is allocated.
constexpr std::uint64_t kMaxColumnSamples = std::uint64_t{1} << 27;

// Contexts are reused by each thread: making one costs more than compressing a small column.
struct ZstdContexts {
    ZstdContexts()
    {
        ZSTD_CCtx_setParameter(compress.get(), ZSTD_c_compressionLevel, kCompressionLevel);
        // A damaged database gives an error, not other numbers.
        ZSTD_CCtx_setParameter(compress.get(), ZSTD_c_checksumFlag, 1);
    }
    std::unique_ptr<ZSTD_CCtx, decltype(&ZSTD_freeCCtx)> compress{ZSTD_createCCtx(), ZSTD_freeCCtx};
    std::unique_ptr<ZSTD_DCtx, decltype(&ZSTD_freeDCtx)> decompress{ZSTD_createDCtx(), ZSTD_freeDCtx};
    std::vector<unsigned char> shuffled;   // scratch, kept between columns
};

ZstdContexts& contexts()
{
    thread_local ZstdContexts c;
    return c;
}

// Appends the column, shuffled and compressed; returns its compressed size.
std::size_t appendCompressed(std::string& out, const double* values, std::size_t n)
{
    ZstdContexts& z = contexts();
    const std::size_t bytes = n * sizeof(double);
    z.shuffled.resize(bytes);
    unsigned char* planes = z.shuffled.data();
    for (std::size_t i = 0; i < n; ++i) {
        std::uint64_t bits;
        std::memcpy(&bits, values + i, sizeof bits);
        for (std::size_t b = 0; b < sizeof(double); ++b) planes[b * n + i] = static_cast<unsigned char>(bits >> (8 * b));
    }
    const std::size_t at = out.size();
    out.resize(at + ZSTD_compressBound(bytes));
    const std::size_t written = ZSTD_compress2(z.compress.get(), out.data() + at, out.size() - at, z.shuffled.data(), bytes);
    if (ZSTD_isError(written)) throw std::runtime_error(std::string("compressing a result: ") + ZSTD_getErrorName(written));
    out.resize(at + written);
    return written;
}

bool decompress(std::string_view compressed, std::uint64_t samples, std::vector<double>& out)
{
    ZstdContexts& z = contexts();
    const std::size_t bytes = samples * sizeof(double);
    if (ZSTD_getFrameContentSize(compressed.data(), compressed.size()) != bytes) return false;
    z.shuffled.resize(bytes);
    const std::size_t got = ZSTD_decompressDCtx(z.decompress.get(), z.shuffled.data(), bytes, compressed.data(),
                                                compressed.size());
    if (ZSTD_isError(got) || got != bytes) return false;
    out.resize(samples);
    auto* raw = reinterpret_cast<unsigned char*>(out.data());
    for (std::size_t b = 0; b < sizeof(double); ++b) {
        const unsigned char* plane = z.shuffled.data() + b * samples;
        for (std::size_t i = 0; i < samples; ++i) raw[i * sizeof(double) + b] = plane[i];
    }
    return true;
}

struct IndexEntry {
    std::string name, unit;
    std::uint64_t samples = 0, compressedBytes = 0;
    std::uint32_t dataOf = 0;
    std::string_view compressed;
};

std::optional<ResultTable> decodeVersion1(std::string_view blob, const std::vector<std::string>& variables)
{
    ResultTable all;
    if (!ResultTable::deserialize(std::string(blob), all)) return std::nullopt;
    if (variables.empty()) return all;
    ResultTable picked;
    picked.time = std::move(all.time);
    for (const auto& name : variables)
        if (const ResultColumn* c = all.column(name)) picked.columns.push_back(*c);
    return picked;
}

} // namespace

std::size_t uncompressedResultBytes(const ResultView& view)
{
    std::size_t n = sizeof kMagic + 4 + 8 + view.numSamples() * sizeof(double) + 4;
    for (std::size_t i = 0; i < view.numVariables(); ++i) {
        const LoggedVariable& v = view.variable(i);
        n += 4 + v.fullName.size() + 4 + v.unit.size() + 8 + view.count(i) * sizeof(double);
    }
    return n;
}

std::string encodeResult(const ResultView& view)
{
    std::string out;
    encodeResult(view, out);
    return out;
}

void encodeResult(const ResultView& view, std::string& out)
{
    // The index first, with each compressed size patched in once its column is written.
    out.clear();
    out.append(kMagic, sizeof kMagic);
    littleEndian::put(out, kVersion);
    littleEndian::put(out, static_cast<std::uint32_t>(view.numVariables() + 1));
    std::vector<std::size_t> sizeAt;
    auto addEntry = [&](const std::string& name, const std::string& unit, std::uint64_t samples, std::uint32_t dataOf) {
        littleEndian::putString(out, name);
        littleEndian::putString(out, unit);
        littleEndian::put(out, samples);
        littleEndian::put(out, dataOf);
        sizeAt.push_back(out.size());
        littleEndian::put<std::uint64_t>(out, 0);
    };
    const auto time = view.time();
    addEntry("", "s", time.size(), 0);
    // Ports on one node log the same samples: such a column is stored once and the others
    // refer to it (Position Servo: 128 columns, 48 distinct).
    std::map<std::tuple<const Node*, int, std::size_t>, std::uint32_t> firstOfSamples;
    std::vector<std::uint32_t> dataOf;
    for (std::size_t i = 0; i < view.numVariables(); ++i) {
        const LoggedVariable& v = view.variable(i);
        const std::size_t samples = view.count(i);
        const auto own = static_cast<std::uint32_t>(i + 1);
        dataOf.push_back(firstOfSamples.try_emplace({v.port->node(), v.slot, samples}, own).first->second);
        addEntry(v.fullName, v.unit, samples, dataOf.back());
    }
    // The stored columns are copied out of the log together (ResultView::copyData), into
    // scratch this thread keeps.
    std::vector<std::size_t> stored;
    std::vector<std::size_t> offsets;
    std::size_t values = 0;
    std::size_t bound = out.size() + ZSTD_compressBound(time.size() * sizeof(double));
    for (std::size_t i = 0; i < view.numVariables(); ++i) {
        if (dataOf[i] != i + 1) continue;
        stored.push_back(i);
        offsets.push_back(values);
        values += view.count(i);
        bound += ZSTD_compressBound(view.count(i) * sizeof(double));
    }
    out.reserve(bound);   // one allocation: each column's resize in appendCompressed fits
    thread_local std::vector<double> samples;
    samples.resize(values);
    std::vector<double*> into;
    for (std::size_t offset : offsets) into.push_back(samples.data() + offset);
    view.copyData(stored, into);

    auto patchSize = [&](std::size_t column, std::uint64_t bytes) {
        std::memcpy(out.data() + sizeAt[column], &bytes, sizeof bytes);
    };
    patchSize(0, appendCompressed(out, time.data(), time.size()));
    for (std::size_t k = 0; k < stored.size(); ++k)
        patchSize(stored[k] + 1, appendCompressed(out, into[k], view.count(stored[k])));
}

std::optional<ResultTable> decodeResult(std::string_view blob, const std::vector<std::string>& variables)
{
    littleEndian::Reader in(blob);
    std::string_view magic;
    std::uint32_t version = 0, columns = 0;
    if (!in.take(sizeof kMagic, magic) || std::memcmp(magic.data(), kMagic, sizeof kMagic) != 0 || !in.get(version))
        return std::nullopt;
    if (version == 1) return decodeVersion1(blob, variables);
    if (version != kVersion || !in.get(columns) || columns == 0) return std::nullopt;
    std::vector<IndexEntry> index(columns);
    for (std::uint32_t i = 0; i < columns; ++i) {
        IndexEntry& e = index[i];
        if (!in.getString(e.name) || !in.getString(e.unit) || !in.get(e.samples) || !in.get(e.dataOf) ||
            !in.get(e.compressedBytes) || e.samples > kMaxColumnSamples || e.dataOf > i)
            return std::nullopt;
        const bool shared = e.dataOf != i;
        if (shared && (e.compressedBytes != 0 || index[e.dataOf].dataOf != e.dataOf ||
                       index[e.dataOf].samples != e.samples || e.dataOf == 0))
            return std::nullopt;
    }
    for (IndexEntry& e : index)
        if (!in.take(e.compressedBytes, e.compressed)) return std::nullopt;
    if (!in.atEnd()) return std::nullopt;

    // Each stored column is decompressed at most once, however many variables share it.
    std::map<std::uint32_t, std::vector<double>> decoded;
    auto samplesOf = [&](const IndexEntry& e) -> const std::vector<double>* {
        auto [it, added] = decoded.try_emplace(e.dataOf);
        if (added && !decompress(index[e.dataOf].compressed, e.samples, it->second)) return nullptr;
        return &it->second;
    };
    ResultTable table;
    const auto* time = samplesOf(index[0]);
    if (!time) return std::nullopt;
    table.time = *time;
    auto addColumn = [&](const IndexEntry& e) {
        const auto* data = samplesOf(e);
        if (!data) return false;
        table.columns.push_back({e.name, e.unit, *data});
        return true;
    };
    if (variables.empty()) {
        for (std::size_t i = 1; i < index.size(); ++i)
            if (!addColumn(index[i])) return std::nullopt;
        return table;
    }
    std::map<std::string_view, const IndexEntry*> byName;
    for (std::size_t i = 1; i < index.size(); ++i) byName.emplace(index[i].name, &index[i]);
    for (const auto& name : variables) {
        const auto it = byName.find(name);
        if (it != byName.end() && !addColumn(*it->second)) return std::nullopt;
    }
    return table;
}

} // namespace tlmhub::server
