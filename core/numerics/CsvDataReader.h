// Indexing CSV reader for tabulated component data (utilities.md §15).
// The text is indexed once (field boundaries per row); only the requested
// columns or rows are converted to numbers.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace tlmhub {

class CsvDataReader
{
public:
    CsvDataReader() = default;

    // Reads the whole file in binary mode. Returns false if it cannot be opened.
    bool openFile(const std::string& path);
    // Uses the given text unchanged as the file contents.
    void openText(const std::string& text);

    void setFieldSeparator(char sep) { mSeparator = sep; }
    char getFieldSeparator() const { return mSeparator; }
    void setLinesToSkip(std::size_t n) { mLinesToSkip = n; }
    // '\0' means "no comment character" (the default).
    void setCommentChar(char c) { mCommentChar = c; }

    // After the skip/comment step, the first byte equal to any candidate
    // becomes the separator (by file position). Returns false (separator
    // unchanged) if none is found.
    bool autoSetSeparator(const std::vector<char>& candidates);

    // Builds the row/field index. Returns false if there is no data region
    // (e.g. more lines to skip than the text has).
    bool indexFile();

    std::size_t getNumDataRows() const { return mRows.size(); }
    // Columns of row r, 0 past the end.
    std::size_t getNumDataCols(std::size_t r = 0) const;

    // All copy functions clear 'out' and return false on a range error or on
    // the first failed field conversion (values converted so far remain).
    bool copyColumn(std::size_t c, std::vector<double>& out) const;
    bool copyRangeFromColumn(std::size_t c, std::size_t start, std::size_t n, std::vector<double>& out) const;
    bool copyEveryNthFromColumn(std::size_t c, std::size_t step, std::vector<double>& out) const;
    bool copyEveryNthFromColumnRange(std::size_t c, std::size_t start, std::size_t n, std::size_t step,
                                     std::vector<double>& out) const;
    bool copyRow(std::size_t r, std::vector<double>& out) const;
    bool copyRow(std::size_t r, std::vector<long>& out) const;

    const std::string& getErrorString() const { return mError; }

    // Field conversion rule (exposed for tests): first ',' -> '.', C strtod,
    // success if it stops at the field end or at white space. Empty -> 0.0.
    static bool convertField(const char* begin, const char* end, double& value);
    static bool convertField(const char* begin, const char* end, long& value);

private:
    struct Field
    {
        std::size_t begin;
        std::size_t end;
    };
    using Row = std::vector<Field>;

    // Position after skipped lines and leading comment lines; false if the
    // skip count runs past the end of the text.
    bool findDataStart(std::size_t& pos) const;
    bool convertAt(const Field& f, double& v) const;

    std::string mData;
    std::vector<Row> mRows;
    std::string mError;
    char mSeparator = ',';
    char mCommentChar = '\0';
    std::size_t mLinesToSkip = 0;
};

} // namespace tlmhub
