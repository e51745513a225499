#include "core/numerics/PloDataReader.h"

#include <fstream>
#include <sstream>

namespace tlmhub {

namespace {

void removeAll(std::string& s, const std::string& what)
{
    std::size_t pos = 0;
    while ((pos = s.find(what, pos)) != std::string::npos) { s.erase(pos, what.size()); }
}

} // namespace

bool PloDataReader::readFile(const std::string& path)
{
    std::ifstream in(path);
    if (!in) {
        mError = "Could not open file: " + path;
        return false;
    }
    return read(in);
}

bool PloDataReader::readText(const std::string& text)
{
    std::istringstream in(text);
    return read(in);
}

bool PloDataReader::read(std::istream& in)
{
    mData.clear();
    mNames.clear();
    mNumCols = 0;
    mNumRows = 0;
    mVersion = 0;
    mError.clear();

    std::string tok;
    if (!(in >> tok) || tok != "'VERSION'") {
        mError = "First token is not 'VERSION'";
        return false;
    }
    if (!(in >> mVersion) || (mVersion != 1 && mVersion != 2)) {
        mError = "Unsupported PLO version";
        return false;
    }
    std::string line;
    std::getline(in, line); // rest of the version line
    std::getline(in, line); // title line

    long nc = 0;
    long nr = 0;
    if (!(in >> nc >> nr) || nc < 1 || nr < 1) {
        mError = "Number of data rows or columns is less than one";
        return false;
    }
    std::size_t cols = static_cast<std::size_t>(nc);
    const std::size_t rows = static_cast<std::size_t>(nr);

    // The header does not count a leading time/frequency column.
    for (std::size_t i = 0; i < cols; ++i) {
        if (!(in >> tok)) {
            mError = "Unexpected end of file in column names";
            return false;
        }
        if (i == 0 && (tok == "'Time'," || tok == "'Frequency',")) { ++cols; }
        removeAll(tok, "',");
        removeAll(tok, "'");
        mNames.push_back(tok);
    }
    for (std::size_t i = 0; i < cols; ++i) { // plot scales / quantities, unused
        if (!(in >> tok)) {
            mError = "Unexpected end of file in plot scales";
            return false;
        }
    }
    std::size_t values = 0;
    if (__builtin_mul_overflow(cols, rows, &values)) {
        mError = "Number of data rows or columns is too large";
        return false;
    }
    // The counts come from the file: values are appended as they are read, so memory
    // follows the file's size, not its header's claim.
    double v = 0;
    while (mData.size() < values && in >> v) { mData.push_back(v); }
    if (mData.size() < values) {
        mData.clear();
        mError = "Could not read all data values";
        return false;
    }
    // Set only now, so a file that fails leaves an empty reader behind.
    mNumCols = cols;
    mNumRows = rows;
    // The two trailing tokens carry nothing we use.
    return true;
}

int PloDataReader::findColumn(const std::string& name) const
{
    for (std::size_t i = 0; i < mNames.size(); ++i) {
        if (mNames[i] == name) { return static_cast<int>(i); }
    }
    return -1;
}

bool PloDataReader::copyColumn(std::size_t c, std::vector<double>& out) const
{
    out.clear();
    if (c >= mNumCols) { return false; }
    out.reserve(mNumRows);
    for (std::size_t r = 0; r < mNumRows; ++r) { out.push_back(mData[r * mNumCols + c]); }
    return true;
}

bool PloDataReader::copyColumn(const std::string& name, std::vector<double>& out) const
{
    const int c = findColumn(name);
    if (c < 0) {
        out.clear();
        return false;
    }
    return copyColumn(static_cast<std::size_t>(c), out);
}

} // namespace tlmhub
