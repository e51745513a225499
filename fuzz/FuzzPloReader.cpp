// Fuzzes the old Hopsan plot-file reader (PloDataReader) and reads back every column.
#include "core/numerics/PloDataReader.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    tlmhub::PloDataReader reader;
    if (!reader.readText(std::string(reinterpret_cast<const char*>(data), size))) return 0;
    std::vector<double> column;
    for (std::size_t c = 0; c <= reader.getNumDataCols(); ++c) reader.copyColumn(c, column);
    for (const std::string& name : reader.getColumnNames()) reader.copyColumn(name, column);
    return 0;
}
