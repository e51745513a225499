#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "core/numerics/CsvDataReader.h"

using namespace tlmhub;

namespace {
std::vector<double> column(CsvDataReader& r, std::size_t c)
{
    std::vector<double> v;
    EXPECT_TRUE(r.copyColumn(c, v));
    return v;
}
} // namespace

TEST(CsvDataReader, BasicColumnsRowsAndLineEnds)
{
    CsvDataReader r;
    r.openText("1,2,3\r\n4,5,6\r\n\r\n\n7,8,9\n");
    ASSERT_TRUE(r.indexFile());
    EXPECT_EQ(r.getNumDataRows(), 3u); // empty lines skipped, no trailing row
    EXPECT_EQ(r.getNumDataCols(0), 3u);
    EXPECT_EQ(r.getNumDataCols(7), 0u);
    EXPECT_EQ(column(r, 1), (std::vector<double>{2.0, 5.0, 8.0}));
    std::vector<double> row;
    ASSERT_TRUE(r.copyRow(2, row));
    EXPECT_EQ(row, (std::vector<double>{7.0, 8.0, 9.0}));
    std::vector<double> none;
    EXPECT_FALSE(r.copyColumn(3, none));
}

TEST(CsvDataReader, SkipLinesAndLeadingCommentsOnly)
{
    CsvDataReader r;
    r.setLinesToSkip(1);
    r.setCommentChar('#');
    r.openText("header line\n#comment\n#another\n1,10\n2,20\n");
    ASSERT_TRUE(r.indexFile());
    EXPECT_EQ(r.getNumDataRows(), 2u);
    EXPECT_EQ(column(r, 1), (std::vector<double>{10.0, 20.0}));

    // A space before '#' is not a comment; a later comment is a data row that fails.
    CsvDataReader s;
    s.setCommentChar('#');
    s.openText(" #x\n1\n#late\n2\n");
    ASSERT_TRUE(s.indexFile());
    EXPECT_EQ(s.getNumDataRows(), 4u);
    std::vector<double> v;
    EXPECT_FALSE(s.copyColumn(0, v));
    // Quirk of the end-of-field rule: for " #x" strtod converts nothing and
    // stops at the leading blank, which counts as success with 0.0.
    EXPECT_EQ(v, (std::vector<double>{0.0, 1.0}));
    EXPECT_TRUE(s.copyRangeFromColumn(0, 1, 1, v));
    EXPECT_EQ(v, std::vector<double>{1.0});
    EXPECT_FALSE(s.copyRangeFromColumn(0, 1, 3, v));
    EXPECT_EQ(v, std::vector<double>{1.0}); // values converted so far remain
}

TEST(CsvDataReader, TooManySkipLinesReportsNoData)
{
    CsvDataReader r;
    r.setLinesToSkip(5);
    r.openText("1\n2\n");
    EXPECT_FALSE(r.indexFile());
    EXPECT_EQ(r.getNumDataRows(), 0u);
}

TEST(CsvDataReader, FieldConversionRules)
{
    CsvDataReader r;
    r.setFieldSeparator(';');
    r.openText("1,5;2\n 1.5 ;\n1.5 abc;  \n1e3;0x10\ninf;-2,25\n");
    ASSERT_TRUE(r.indexFile());
    EXPECT_EQ(column(r, 0), (std::vector<double>{1.5, 1.5, 1.5, 1000.0, INFINITY}));
    // Empty and blank fields give 0.0; hex floats accepted; decimal comma.
    EXPECT_EQ(column(r, 1), (std::vector<double>{2.0, 0.0, 0.0, 16.0, -2.25}));

    double v = -1.0;
    const std::string bad = "1.5abc";
    EXPECT_FALSE(CsvDataReader::convertField(bad.data(), bad.data() + bad.size(), v));
    const std::string word = "abc";
    EXPECT_FALSE(CsvDataReader::convertField(word.data(), word.data() + word.size(), v));
    const std::string twoCommas = "1,5,3";
    EXPECT_FALSE(CsvDataReader::convertField(twoCommas.data(), twoCommas.data() + twoCommas.size(), v));
}

TEST(CsvDataReader, AdjacentAndTrailingSeparatorsGiveEmptyFields)
{
    CsvDataReader r;
    r.openText("1,,3,\n4,5,6,7\n");
    ASSERT_TRUE(r.indexFile());
    EXPECT_EQ(r.getNumDataCols(0), 4u);
    std::vector<double> row;
    ASSERT_TRUE(r.copyRow(0, row));
    EXPECT_EQ(row, (std::vector<double>{1.0, 0.0, 3.0, 0.0}));
}

TEST(CsvDataReader, SpaceSeparator)
{
    CsvDataReader r;
    r.setFieldSeparator(' ');
    r.openText("  1   2  3\n4 5 6 \n");
    ASSERT_TRUE(r.indexFile());
    EXPECT_EQ(r.getNumDataCols(0), 3u); // leading spaces ignored, runs are one boundary
    EXPECT_EQ(r.getNumDataCols(1), 4u); // trailing space adds an empty field
    EXPECT_EQ(column(r, 2), (std::vector<double>{3.0, 6.0}));

    // Tab is not a separator unless chosen.
    CsvDataReader t;
    t.openText("1\t2\n");
    ASSERT_TRUE(t.indexFile());
    EXPECT_EQ(t.getNumDataCols(0), 1u);
}

TEST(CsvDataReader, LeadingLineEndBecomesEmptyRow)
{
    CsvDataReader r;
    r.openText("\n1,2\n3,4\n");
    ASSERT_TRUE(r.indexFile());
    EXPECT_EQ(r.getNumDataRows(), 3u);
    EXPECT_EQ(r.getNumDataCols(0), 1u);
    EXPECT_EQ(column(r, 0), (std::vector<double>{0.0, 1.0, 3.0}));
    std::vector<double> v;
    EXPECT_FALSE(r.copyColumn(1, v)); // checked against the first (empty) row
}

TEST(CsvDataReader, EveryNthAndIntegerRows)
{
    CsvDataReader r;
    r.openText("0,5\n1,6\n2,7\n3,8\n4,9\n5,10\n6,11\n");
    ASSERT_TRUE(r.indexFile());
    std::vector<double> v;
    ASSERT_TRUE(r.copyEveryNthFromColumn(0, 3, v));
    EXPECT_EQ(v, (std::vector<double>{0.0, 3.0, 6.0}));
    ASSERT_TRUE(r.copyEveryNthFromColumnRange(1, 1, 5, 2, v));
    EXPECT_EQ(v, (std::vector<double>{6.0, 8.0, 10.0}));
    EXPECT_FALSE(r.copyRangeFromColumn(0, 5, 3, v)); // past the last row
    std::vector<long> iv;
    ASSERT_TRUE(r.copyRow(3, iv));
    EXPECT_EQ(iv, (std::vector<long>{3, 8}));
}

TEST(CsvDataReader, AutoSeparatorChoosesFirstByPosition)
{
    CsvDataReader r;
    r.setLinesToSkip(1);
    r.openText("a,b;c\n1;2,5\n");
    ASSERT_TRUE(r.autoSetSeparator({',', ';'}));
    EXPECT_EQ(r.getFieldSeparator(), ';');
    ASSERT_TRUE(r.indexFile());
    EXPECT_EQ(column(r, 1), std::vector<double>{2.5});
    EXPECT_FALSE(r.autoSetSeparator({'\t'}));
    EXPECT_EQ(r.getFieldSeparator(), ';');
}

TEST(CsvDataReader, ReadsFromFile)
{
    const std::string path = ::testing::TempDir() + "tlmhub_csv_test.csv";
    {
        std::ofstream f(path, std::ios::binary);
        f << "0,1.5\r1,2.5";
    }
    CsvDataReader r;
    ASSERT_TRUE(r.openFile(path));
    ASSERT_TRUE(r.indexFile());
    EXPECT_EQ(column(r, 1), (std::vector<double>{1.5, 2.5}));
    std::remove(path.c_str());
    EXPECT_FALSE(r.openFile(path + ".missing"));
}

TEST(CsvDataReader, RangeWhoseEndOverflowsIsRefused)
{
    CsvDataReader r;
    r.openText("1,2\n3,4\n5,6\n");
    ASSERT_TRUE(r.indexFile());
    std::vector<double> out;
    // start + n wraps around to 0 in size_t: it must not pass the bounds check.
    EXPECT_FALSE(r.copyRangeFromColumn(0, 1, SIZE_MAX, out));
    EXPECT_TRUE(out.empty());
    EXPECT_FALSE(r.copyEveryNthFromColumnRange(1, 2, SIZE_MAX - 1, 2, out));
}
