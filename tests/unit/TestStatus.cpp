// describe(): the one text of a Status for people, shared by the CLI and validation reports.
#include "core/Status.h"

#include <gtest/gtest.h>

using namespace tlmhub;

TEST(Status, DescribeGivesCodeAndMessage)
{
    EXPECT_EQ(describe({StatusCode::IoError, "cannot write 'out.csv'"}), "io_error: cannot write 'out.csv'");
}

TEST(Status, DescribeNamesTheModelPath)
{
    EXPECT_EQ(describe({StatusCode::InvalidParameter, "'heavy' is not defined", "Sub$Mass.m"}),
              "invalid_parameter: 'heavy' is not defined (at Sub$Mass.m)");
}
