#pragma once
// How a job's result is stored: every column (time first) compressed on its own, so reading
// one variable decompresses only that one, and values come back exactly. A column's 8-byte
// values are byte-shuffled before zstd (all first bytes, then all second bytes, ...): signs,
// exponents and leading mantissa bytes of neighbouring samples are alike, and lined up they
// compress far better than interleaved. Ports on one node log the same samples; their columns
// are stored once. Position Servo: 2.1 MB as float64, 0.53 MB stored.
//
// Layout (version 2, integers little-endian):
//   "TLRT" u32 2 | u32 columns |
//   per column (time first, with an empty name): u32 len, name | u32 len, unit |
//       u64 samples | u32 data of (the column whose stored data these samples are: itself,
//       or an earlier one) | u64 compressed bytes (0 when the data is another column's) |
//   the compressed columns (zstd frames with checksums), in the same order.
// Version 1 (ResultTable::serialize, uncompressed) is still read: results stored before.
#include "core/ResultTable.h"
#include "core/ResultView.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tlmhub::server {

// The run's logged samples, in the view's order and names.
std::string encodeResult(const ResultView& view);
// The same into `out`, whose capacity is reused (a worker stores result after result).
void encodeResult(const ResultView& view, std::string& out);
// What the result weighs as float64 columns (ResultTable::byteSize of it), the size the
// result limit applies to.
std::size_t uncompressedResultBytes(const ResultView& view);
// The stored result with the columns `variables` names, in that order (unknown names are
// skipped; empty: all); nullopt if `blob` is not a stored result.
std::optional<ResultTable> decodeResult(std::string_view blob, const std::vector<std::string>& variables = {});

} // namespace tlmhub::server
