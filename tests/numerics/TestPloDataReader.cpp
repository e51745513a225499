#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/numerics/PloDataReader.h"

using namespace tlmhub;

TEST(PloDataReader, ReadsVersion1WithTimeColumn)
{
    const std::string plo =
        "'VERSION' 1 extra stuff\n"
        "'title line with words'\n"
        "2 3\n"
        "'Time',    'Pressure',    'Flow'\n"
        "1.0 1.0 1.0\n"
        "0.0  100.0  -1.0\n"
        "0.5  200.0  -2.0\n"
        "1.0  300.0  -3.0\n"
        "'Z' 'END'\n";
    PloDataReader r;
    ASSERT_TRUE(r.readText(plo)) << r.getErrorString();
    EXPECT_EQ(r.getVersion(), 1);
    EXPECT_EQ(r.getNumDataCols(), 3u); // time column added to the header count
    EXPECT_EQ(r.getNumDataRows(), 3u);
    EXPECT_EQ(r.getColumnNames(), (std::vector<std::string>{"Time", "Pressure", "Flow"}));
    std::vector<double> v;
    ASSERT_TRUE(r.copyColumn("Pressure", v));
    EXPECT_EQ(v, (std::vector<double>{100.0, 200.0, 300.0}));
    ASSERT_TRUE(r.copyColumn(0, v));
    EXPECT_EQ(v, (std::vector<double>{0.0, 0.5, 1.0}));
    EXPECT_FALSE(r.copyColumn("Missing", v));
    EXPECT_FALSE(r.copyColumn(3, v));
}

TEST(PloDataReader, RejectsBadHeaders)
{
    PloDataReader r;
    EXPECT_FALSE(r.readText("VERSION 1\nt\n1 1\n'a'\n1\n1\n"));
    EXPECT_FALSE(r.readText("'VERSION' 3\nt\n1 1\n'a'\n1\n1\n"));
    EXPECT_FALSE(r.readText("'VERSION' 2\nt\n0 1\n"));
    EXPECT_FALSE(r.readText("'VERSION' 2\nt\n2 2\n'a', 'b'\n1 1\n1 2 3\n")); // too few values
    ASSERT_TRUE(r.readText("'VERSION' 2\nt\n2 1\n'a', 'b'\n1 1\n7 8\nx y\n"));
    EXPECT_EQ(r.getNumDataCols(), 2u);
    std::vector<double> v;
    ASSERT_TRUE(r.copyColumn("b", v));
    EXPECT_EQ(v, std::vector<double>{8.0});
}

// Found by fuzz/FuzzPloReader: the header's counts sized the data before any value was read.
TEST(PloDataReader, HeaderClaimingHugeCountsIsAnErrorNotAnAllocation)
{
    PloDataReader r;
    EXPECT_FALSE(r.readText("'VERSION' 1\nt\n2 1000000000000\n'a' 'b'\ns s\n1 2\n"));
    EXPECT_EQ(r.getErrorString(), "Could not read all data values");
}

TEST(PloDataReader, CountsWhoseProductOverflowsAreRefused)
{
    // 4 * 2^62 is 0 in 64 bits: the reader must not accept zero values for 2^62 rows.
    PloDataReader r;
    EXPECT_FALSE(r.readText("'VERSION' 1\nt\n4 4611686018427387904\n'a' 'b' 'c' 'd'\ns s s s\n"));
    EXPECT_EQ(r.getNumDataRows(), 0u);
    std::vector<double> v;
    EXPECT_FALSE(r.copyColumn(0, v));
}
