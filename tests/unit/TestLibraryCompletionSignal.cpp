// Signal types completing Hopsan's default library (issue 21): the 2D signal read/write
// pair, the obsolete LookUpTable2D and the optimisation test functions. Each is checked
// against a closed-form value and run in a small model to its stop time.
#include "TestHelpers.h"

#include "core/Results.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

using namespace tlmhub;
using namespace tlmhub::test;

namespace lcsignal {

std::vector<double> loggedValues(System& s, const std::string& comp, const std::string& port,
                                 const std::string& var = "Value")
{
    Port* p = s.component(comp)->port(port);
    return loggedData(*p, nodeVariableIndex(p->nodeType(), var), s.numLoggedSamples());
}

// All digits, where std::to_string would round to six decimals.
std::string exact(double v)
{
    std::ostringstream out;
    out << std::setprecision(17) << v;
    return out.str();
}

// Output of a lone function component at one point, after a two-step run.
double evaluate(const std::string& type, int function, const std::vector<std::pair<std::string, double>>& inputs)
{
    System s;
    add(s, type, "F");
    setParam(s, "F", "function", std::to_string(function));
    for (const auto& [name, value] : inputs) setParam(s, "F", name + "#Value", exact(value));
    EXPECT_TRUE(run(s, 0, 0.002, 1e-3, 3));
    return loggedValues(s, "F", "out").back();
}

double evaluate2D(int function, double x, double y)
{
    return evaluate("OptimizationTestFunction2D", function, {{"x", x}, {"y", y}});
}

} // namespace lcsignal

using namespace lcsignal;

TEST(LibraryCompletionSignal2D, WriteThenReadRoundTripsAVectorInTheSameStep)
{
    // in1 = time, in2 = constant; the reader must see this step's values (exactly).
    System s;
    add(s, "SignalTime", "Clock");
    add(s, "Signal2DRead", "Read");     // added first, so only sorting puts it after the writer
    add(s, "Signal2DWrite", "Write");
    connectOk(s, "Clock", "out", "Write", "in1");
    connectOk(s, "Write", "P2d", "Read", "P2d");
    setParam(s, "Write", "in2#Value", "-7.25");
    ASSERT_TRUE(run(s, 0, 1, 1e-3, 101));
    const auto out1 = loggedValues(s, "Read", "out1");
    const auto out2 = loggedValues(s, "Read", "out2");
    const auto& t = s.logTime();
    ASSERT_EQ(out1.size(), t.size());
    for (std::size_t i = 0; i < t.size(); ++i) {
        EXPECT_DOUBLE_EQ(out1[i], t[i]) << "t=" << t[i];
        EXPECT_DOUBLE_EQ(out2[i], -7.25) << "t=" << t[i];
    }
}

TEST(LibraryCompletionSignal2D, ReadAloneGivesTheNodeStartValues)
{
    System s;
    add(s, "Signal2DRead", "Read");
    setParam(s, "Read", "P2d#v0", "1.5");
    setParam(s, "Read", "P2d#v1", "2.5");
    ASSERT_TRUE(run(s, 0, 0.01, 1e-3, 11));
    EXPECT_DOUBLE_EQ(loggedValues(s, "Read", "out1").back(), 1.5);
    EXPECT_DOUBLE_EQ(loggedValues(s, "Read", "out2").back(), 2.5);
}

TEST(LibraryCompletionSignalLookUpTable2D, InterpolatesLinearlyAndHoldsTheEnds)
{
    namespace fs = std::filesystem;
    const fs::path file = fs::temp_directory_path() / "tlmhub-lookuptable2d-test.csv";
    {
        std::ofstream out(file);
        out << "2;40;-1\n0;0;5\n1;10;6\n";   // unsorted on purpose: the table sorts its index
    }
    auto valueAt = [&](double in, int outid) {
        System s;
        add(s, "SignalLookUpTable2D", "Table");
        setParam(s, "Table", "filename", file.string());
        setParam(s, "Table", "csvsep", ";");
        setParam(s, "Table", "outid", std::to_string(outid));
        setParam(s, "Table", "in#Value", exact(in));
        EXPECT_TRUE(run(s, 0, 0.002, 1e-3, 3));
        return loggedValues(s, "Table", "out").back();
    };
    EXPECT_NEAR(valueAt(0.5, 1), 5.0, 1e-12);
    EXPECT_NEAR(valueAt(1.5, 1), 25.0, 1e-12);
    EXPECT_NEAR(valueAt(-3.0, 1), 0.0, 1e-12);
    EXPECT_NEAR(valueAt(9.0, 1), 40.0, 1e-12);
    EXPECT_NEAR(valueAt(1.5, 2), 2.5, 1e-12);

    // Driven by time over [0, 3]: finite, and equal to the table at t = 1.5 and past its end.
    System s;
    add(s, "SignalTime", "Clock");
    add(s, "SignalLookUpTable2D", "Table");
    connectOk(s, "Clock", "out", "Table", "in");
    setParam(s, "Table", "filename", file.string());
    setParam(s, "Table", "csvsep", ";");
    ASSERT_TRUE(run(s, 0, 3, 1e-3, 301));
    const auto out = loggedValues(s, "Table", "out");
    for (double v : out) EXPECT_TRUE(std::isfinite(v));
    EXPECT_NEAR(out[150], 25.0, 1e-9);
    EXPECT_NEAR(out.back(), 40.0, 1e-12);
    fs::remove(file);
}

TEST(LibraryCompletionSignalLookUpTable2D, AMissingFileStopsTheSimulation)
{
    System s;
    add(s, "SignalLookUpTable2D", "Table");
    setParam(s, "Table", "filename", "/nonexistent/tlmhub-table.csv");
    EXPECT_FALSE(run(s, 0, 0.01, 1e-3, 11));
}

TEST(LibraryCompletionOptimizationTestFunction2D, KnownMinimaAndLargerValuesNearby)
{
    // {function index, argmin x, y, minimum, tolerance}; published minima, rounded as published.
    struct Case { int f; double x, y, min, tol; };
    const double pi = 3.14159265358979323846;
    const Case cases[] = {
        {0, 0.0, 0.0, 2.71828 - std::exp(1.0), 1e-12},   // Ackley with Hopsan's 2.71828
        {2, 1.0, 3.0, 0.0, 1e-12},                        // Booth
        {3, -10.0, 1.0, 0.0, 1e-12},                      // Bukin N.6
        {4, 1.34941, 1.34941, -2.06261, 1e-5},            // cross-in-tray
        {5, pi, pi, -1.0, 1e-12},                         // Easom
        {7, 0.0, -1.0, 3.0, 1e-12},                       // Goldstein-Price
        {8, 8.05502, 9.66459, -19.2085, 1e-4},            // Holder table
        {9, 1.0, 1.0, 0.0, 1e-12},                        // Levi N.13
        {10, 0.0, 0.0, 0.0, 1e-12},                       // Matyas
        {11, -0.54719, -1.54719, -1.9133, 1e-4},          // McCormick
        {13, 1.0, 1.0, 0.0, 1e-12},                       // Rosenbrock
        {14, 0.0, 0.0, 0.0, 1e-12},                       // Schaffer N.2
        {16, 0.0, 0.0, 0.0, 1e-12},                       // sphere
        {17, -2.903534, -2.903534, -78.33233, 1e-4},      // Styblinski-Tang
        {18, 0.0, 0.0, 0.0, 1e-12},                       // three-hump camel
    };
    for (const Case& c : cases) {
        EXPECT_NEAR(evaluate2D(c.f, c.x, c.y), c.min, c.tol) << "function " << c.f;
        EXPECT_GT(evaluate2D(c.f, c.x - 0.1, c.y + 0.1), c.min + c.tol) << "function " << c.f;
    }
    // Peaks (MATLAB's): its value at the origin is 3 e^-1 - e^-1 / 3 = 8/3 e^-1.
    EXPECT_NEAR(evaluate2D(12, 0.0, 0.0), 8.0 / 3.0 * std::exp(-1.0), 1e-12);
    // Eggholder and Schaffer N.4 as Hopsan writes them (no square root in the eggholder's
    // second sine; cos instead of cos^2 in Schaffer N.4): closed-form values at chosen points.
    EXPECT_NEAR(evaluate2D(6, 0.0, 0.0), -47.0 * std::sin(std::sqrt(47.0)), 1e-12);
    EXPECT_NEAR(evaluate2D(6, 2.0, -47.0), -2.0 * std::sin(2.0), 1e-12);
    EXPECT_NEAR(evaluate2D(15, 3.0, 3.0), 0.5 + 0.5 / std::pow(1.018, 2), 1e-12);   // x^2 = y^2
    const double r = std::sqrt(pi / 2.0);
    EXPECT_NEAR(evaluate2D(15, r, 0.0), 0.5 + (std::cos(1.0) - 0.5) / std::pow(1.0 + 0.001 * pi / 2.0, 2), 1e-12);
    // Beale as Hopsan writes it, with 15 in the first term: 15^2 + 2.25^2 + 2.625^2 at the origin.
    EXPECT_NEAR(evaluate2D(1, 0.0, 0.0), 225.0 + 2.25 * 2.25 + 2.625 * 2.625, 1e-12);
}

TEST(LibraryCompletionOptimizationTestFunction5D6D, KnownMinimaAndLargerValuesNearby)
{
    for (int n : {5, 6}) {
        const std::string type = "OptimizationTestFunction" + std::to_string(n) + "D";
        auto at = [&](int f, double v, double bump) {
            std::vector<std::pair<std::string, double>> in;
            for (int i = 1; i <= n; ++i) in.push_back({"x" + std::to_string(i), i == 2 ? v + bump : v});
            return evaluate(type, f, in);
        };
        EXPECT_NEAR(at(0, 1.0, 0.0), 0.0, 1e-12) << type;            // Rosenbrock at (1, ..., 1)
        EXPECT_GT(at(0, 1.0, 0.1), 0.5) << type;                     // 100 * 0.1^2 + more
        EXPECT_NEAR(at(1, 0.0, 0.0), 0.0, 1e-12) << type;            // sphere at the origin
        EXPECT_NEAR(at(1, 2.0, 0.0), 4.0 * n, 1e-12) << type;
        EXPECT_NEAR(at(2, -2.903534, 0.0), -39.16617 * n, 1e-4 * n) << type;   // Styblinski-Tang
        EXPECT_GT(at(2, -2.903534, 0.2), -39.16617 * n + 0.1) << type;
    }
}

TEST(LibraryCompletionOptimizationTestFunction2D, FollowsMovingInputsInAModel)
{
    // Sphere of (sin 2 pi t, cos 2 pi t) is 1 at every step.
    System s;
    add(s, "SignalSineWave", "Sin");
    add(s, "SignalSineWave", "Cos");
    add(s, "OptimizationTestFunction2D", "F");
    connectOk(s, "Sin", "out", "F", "x");
    connectOk(s, "Cos", "out", "F", "y");
    setParam(s, "F", "function", "16");
    setParam(s, "Cos", "y_offset#Value", "-0.25");   // sin(2 pi (t + 1/4)) = cos(2 pi t)
    ASSERT_TRUE(run(s, 0, 2, 1e-3, 201));
    for (double v : loggedValues(s, "F", "out")) EXPECT_NEAR(v, 1.0, 1e-9);
}
