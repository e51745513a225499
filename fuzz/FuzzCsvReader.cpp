// Fuzzes the CSV reader (CsvDataReader): the first three bytes choose the lines to skip, the
// comment character and whether the separator is detected; the rest is the file text. Every
// column of the first row and every row are converted.
#include "core/numerics/CsvDataReader.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    if (size < 3) return 0;
    tlmhub::CsvDataReader reader;
    reader.setLinesToSkip(data[0] % 4);
    reader.setCommentChar(data[1] % 2 ? '#' : '\0');
    if (data[2] % 2) reader.setFieldSeparator(';');
    reader.openText(std::string(reinterpret_cast<const char*>(data) + 3, size - 3));
    if (data[2] & 2) reader.autoSetSeparator({',', ';', '\t', ' '});
    if (!reader.indexFile()) return 0;

    std::vector<double> values;
    std::vector<long> integers;
    const std::size_t rows = reader.getNumDataRows();
    for (std::size_t c = 0; c <= reader.getNumDataCols(); ++c) {
        reader.copyColumn(c, values);
        reader.copyRangeFromColumn(c, rows / 2, rows, values);
        reader.copyEveryNthFromColumn(c, 1 + data[0] % 3, values);
        reader.copyEveryNthFromColumnRange(c, 1, rows, 2, values);
    }
    for (std::size_t r = 0; r <= rows; ++r) {
        reader.copyRow(r, values);
        reader.copyRow(r, integers);
    }
    return 0;
}
