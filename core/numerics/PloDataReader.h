// Reader for the old Hopsan plot-file format (.plo), used by the PLO lookup
// table component (utilities.md §15.6).
#pragma once

#include <cstddef>
#include <istream>
#include <string>
#include <vector>

namespace tlmhub {

class PloDataReader
{
public:
    bool readFile(const std::string& path);
    bool readText(const std::string& text);
    bool read(std::istream& in);

    int getVersion() const { return mVersion; }
    std::size_t getNumDataCols() const { return mNumCols; }
    std::size_t getNumDataRows() const { return mNumRows; }
    const std::vector<std::string>& getColumnNames() const { return mNames; }
    // Index of the first column whose cleaned name matches exactly, or -1.
    int findColumn(const std::string& name) const;

    bool copyColumn(std::size_t c, std::vector<double>& out) const;
    bool copyColumn(const std::string& name, std::vector<double>& out) const;

    const std::string& getErrorString() const { return mError; }

private:
    std::vector<double> mData; // row-major, mNumRows * mNumCols
    std::vector<std::string> mNames;
    std::size_t mNumCols = 0;
    std::size_t mNumRows = 0;
    int mVersion = 0;
    std::string mError;
};

} // namespace tlmhub
