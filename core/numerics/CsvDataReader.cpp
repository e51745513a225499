#include "core/numerics/CsvDataReader.h"

#include <cctype>
#include <cstdlib>
#include <fstream>
#include <iterator>

namespace tlmhub {

namespace {

bool isLineEnd(char ch) { return ch == '\n' || ch == '\r'; }

// Copies a field into a NUL-terminated buffer with the first ',' turned into
// '.' (decimal-comma support).
std::string prepareField(const char* begin, const char* end)
{
    std::string buf(begin, end);
    const auto comma = buf.find(',');
    if (comma != std::string::npos) { buf[comma] = '.'; }
    return buf;
}

bool stoppedAtFieldEnd(const char* stop) { return *stop == '\0' || std::isspace(static_cast<unsigned char>(*stop)); }

} // namespace

bool CsvDataReader::openFile(const std::string& path)
{
    std::ifstream file(path, std::ios::in | std::ios::binary);
    if (!file) {
        mError = "Could not open file: " + path;
        return false;
    }
    mData.assign(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
    mRows.clear();
    mError.clear();
    return true;
}

void CsvDataReader::openText(const std::string& text)
{
    mData = text;
    mRows.clear();
    mError.clear();
}

bool CsvDataReader::findDataStart(std::size_t& pos) const
{
    pos = 0;
    for (std::size_t s = 0; s < mLinesToSkip; ++s) {
        const std::size_t nl = mData.find('\n', pos);
        if (nl == std::string::npos) {
            pos = mData.size();
            return false; // the reference would hang here; we report no data
        }
        pos = nl + 1;
    }
    if (mCommentChar != '\0') {
        // Only lines whose very first byte is the comment character.
        while (pos < mData.size() && mData[pos] == mCommentChar) {
            const std::size_t nl = mData.find('\n', pos);
            pos = (nl == std::string::npos) ? mData.size() : nl + 1;
        }
    }
    return true;
}

bool CsvDataReader::autoSetSeparator(const std::vector<char>& candidates)
{
    std::size_t pos = 0;
    if (!findDataStart(pos)) { return false; }
    for (; pos < mData.size(); ++pos) {
        for (char c : candidates) {
            if (mData[pos] == c) {
                mSeparator = c;
                return true;
            }
        }
    }
    return false;
}

bool CsvDataReader::indexFile()
{
    mRows.clear();
    std::size_t i = 0;
    if (!findDataStart(i)) {
        mError = "More lines to skip than lines in the data";
        return false;
    }
    const std::size_t n = mData.size();
    const bool spaceSep = (mSeparator == ' ');
    if (i >= n) { return true; } // empty data region: zero rows

    auto skipSpaces = [&]() {
        if (spaceSep) {
            while (i < n && mData[i] == ' ') { ++i; }
        }
    };

    Row cur;
    skipSpaces(); // leading spaces are ignored when space is the separator
    std::size_t fieldBegin = i;
    bool rowOpen = true;
    while (i < n) {
        const char ch = mData[i];
        if (isLineEnd(ch)) {
            cur.push_back({fieldBegin, i});
            mRows.push_back(cur);
            cur.clear();
            while (i < n && isLineEnd(mData[i])) { ++i; } // a run of line ends is one break
            if (i >= n) {
                rowOpen = false;
                break;
            }
            skipSpaces();
            fieldBegin = i;
        } else if (ch == mSeparator) {
            cur.push_back({fieldBegin, i});
            ++i;
            skipSpaces(); // a run of spaces is a single boundary
            fieldBegin = i;
        } else {
            ++i;
        }
    }
    if (rowOpen) {
        cur.push_back({fieldBegin, n});
        mRows.push_back(cur);
    }
    return true;
}

std::size_t CsvDataReader::getNumDataCols(std::size_t r) const
{
    return (r < mRows.size()) ? mRows[r].size() : 0;
}

bool CsvDataReader::convertField(const char* begin, const char* end, double& value)
{
    const std::string buf = prepareField(begin, end);
    char* stop = nullptr;
    value = std::strtod(buf.c_str(), &stop);
    return stoppedAtFieldEnd(stop);
}

bool CsvDataReader::convertField(const char* begin, const char* end, long& value)
{
    const std::string buf = prepareField(begin, end);
    char* stop = nullptr;
    value = std::strtol(buf.c_str(), &stop, 10);
    return stoppedAtFieldEnd(stop);
}

bool CsvDataReader::convertAt(const Field& f, double& v) const
{
    return convertField(mData.data() + f.begin, mData.data() + f.end, v);
}

bool CsvDataReader::copyRangeFromColumn(std::size_t c, std::size_t start, std::size_t n,
                                        std::vector<double>& out) const
{
    return copyEveryNthFromColumnRange(c, start, n, 1, out);
}

bool CsvDataReader::copyColumn(std::size_t c, std::vector<double>& out) const
{
    return copyEveryNthFromColumnRange(c, 0, mRows.size(), 1, out);
}

bool CsvDataReader::copyEveryNthFromColumn(std::size_t c, std::size_t step, std::vector<double>& out) const
{
    return copyEveryNthFromColumnRange(c, 0, mRows.size(), step, out);
}

bool CsvDataReader::copyEveryNthFromColumnRange(std::size_t c, std::size_t start, std::size_t n, std::size_t step,
                                                std::vector<double>& out) const
{
    out.clear();
    if (step == 0) { return false; }
    // Written so that start + n cannot wrap around.
    if (start > mRows.size() || n > mRows.size() - start || n == 0) { return n == 0 && start <= mRows.size(); }
    // Like the reference, the column is checked against the first requested row.
    if (c >= mRows[start].size()) { return false; }
    out.reserve(n / step + 1);
    for (std::size_t k = 0; k < n; ++k) {
        const Row& row = mRows[start + k];
        if (c >= row.size()) { return false; } // the reference reads out of row here; we refuse
        double v = 0.0;
        if (!convertAt(row[c], v)) { return false; }
        if (k % step == 0) { out.push_back(v); }
    }
    return true;
}

bool CsvDataReader::copyRow(std::size_t r, std::vector<double>& out) const
{
    out.clear();
    if (r >= mRows.size()) { return false; }
    for (const Field& f : mRows[r]) {
        double v = 0.0;
        if (!convertAt(f, v)) { return false; }
        out.push_back(v);
    }
    return true;
}

bool CsvDataReader::copyRow(std::size_t r, std::vector<long>& out) const
{
    out.clear();
    if (r >= mRows.size()) { return false; }
    for (const Field& f : mRows[r]) {
        long v = 0;
        if (!convertField(mData.data() + f.begin, mData.data() + f.end, v)) { return false; }
        out.push_back(v);
    }
    return true;
}

} // namespace tlmhub
