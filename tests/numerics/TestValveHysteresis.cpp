#include <gtest/gtest.h>

#include "core/numerics/ValveHysteresis.h"

using namespace tlmhub;

TEST(ValveHysteresis, HoldsInsideBandAndIsDraggedOutside)
{
    ValveHysteresis hyst;
    // Band around xs = 1 with width 0.5: [0.75, 1.25].
    EXPECT_EQ(hyst.getValue(1.0, 0.5, 1.1), 1.1);
    EXPECT_EQ(hyst.getValue(1.0, 0.5, 0.0), 0.75);
    EXPECT_EQ(hyst.getValue(1.0, 0.5, 2.0), 1.25);
    EXPECT_EQ(hyst.getValue(1.0, 0.5, 0.75), 0.75);
    EXPECT_EQ(hyst.getValue(3.0, 0.0, 1.0), 3.0); // zero width: follows input

    // A sweep up then down shows play of total width xh.
    double y = 0.0;
    for (double x : {0.0, 0.2, 0.4, 0.6, 0.8, 1.0}) { y = hyst.getValue(x, 0.4, y); }
    EXPECT_DOUBLE_EQ(y, 0.8);
    y = hyst.getValue(0.7, 0.4, y); // reversing within the play holds the output
    EXPECT_DOUBLE_EQ(y, 0.8);
    y = hyst.getValue(0.5, 0.4, y);
    EXPECT_DOUBLE_EQ(y, 0.7);
}
