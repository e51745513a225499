// The loader's outcome as a Status: which code a model text that does not load gets.
#include "TestHelpers.h"

#include "core/hmf/HmfLoader.h"

using namespace tlmhub;

namespace {

const char* kModelWithTeapot = R"(<hopsanmodelfile hopsancoreversion="2.14.0">
  <system typename="Subsystem" name="Root">
    <objects>
      <component typename="HydraulicTeapot" name="Pot"/>
    </objects>
  </system>
</hopsanmodelfile>)";

} // namespace

TEST(LoadStatus, AModelThatLoadsIsOk)
{
    const LoadedModel loaded = loadHmfString(R"(<hopsanmodelfile><system name="Root"/></hopsanmodelfile>)", "");
    EXPECT_TRUE(test::isOk(loaded.status()));
}

TEST(LoadStatus, AnUnknownTypeIsNamedWithItsCode)
{
    const Status status = loadHmfString(kModelWithTeapot, "", "teapot.hmf").status();
    EXPECT_EQ(status.code(), StatusCode::UnknownComponentType) << status.codeName();
    EXPECT_NE(status.message().find("HydraulicTeapot"), std::string::npos) << status.message();
    EXPECT_NE(status.message().find("teapot.hmf"), std::string::npos) << status.message();
}

TEST(LoadStatus, TextThatIsNoModelAndLimitsAreInvalidModel)
{
    EXPECT_EQ(loadHmfString("<hopsanmodelfile><system", "").status().code(), StatusCode::InvalidModel);
    EXPECT_EQ(loadHmfString("<html/>", "").status().code(), StatusCode::InvalidModel);
    LoadLimits tiny;
    tiny.maxComponents = 1;
    const std::string two = R"(<hopsanmodelfile><system name="Root"><objects>
        <component typename="SignalGain" name="A"/><component typename="SignalGain" name="B"/>
        </objects></system></hopsanmodelfile>)";
    EXPECT_TRUE(test::isOk(loadHmfString(two, "").status()));
    const Status limited = loadHmfString(two, "", "two.hmf", tiny).status();
    EXPECT_EQ(limited.code(), StatusCode::InvalidModel);
    EXPECT_NE(limited.message().find("limit"), std::string::npos) << limited.message();
}

TEST(LoadStatus, AMissingFileIsAnIoError)
{
    EXPECT_EQ(loadHmfFile("/nonexistent/model.hmf").status().code(), StatusCode::IoError);
}
