// With model file access off (the server's setting), a component that opens a file fails
// with a message saying so, and an external subsystem is refused when loading.
#include "TestHelpers.h"

#include "core/FileAccess.h"
#include "core/hmf/HmfLoader.h"

using namespace tlmhub;
using namespace tlmhub::test;

namespace {
struct FileAccessOff {
    FileAccessOff() { setModelFileAccess(false); }
    ~FileAccessOff() { setModelFileAccess(true); }
};

bool anyMessageContains(const std::vector<Message>& messages, const std::string& text)
{
    for (const Message& m : messages)
        if (m.text.find(text) != std::string::npos) return true;
    return false;
}
} // namespace

TEST(FileAccess, LookupTableCannotReadHostFilesWhenOff)
{
    FileAccessOff off;
    System s;
    add(s, "Signal1DLookupTable", "Table");
    setParam(s, "Table", "filename", "/etc/passwd");
    EXPECT_FALSE(run(s, 0, 0.01, 1e-3, 11));
    EXPECT_TRUE(anyMessageContains(s.messages(), "file access is disabled"));
}

TEST(FileAccess, ExternalSubsystemIsRefusedWhenOff)
{
    FileAccessOff off;
    const std::string hmf = R"(<?xml version="1.0"?>
<hopsanmodelfile hmfversion="0.4" hopsanguiversion="2.9" hopsancoreversion="2.9">
  <system typename="Subsystem" name="Top">
    <simulationtime start="0" stop="1" timestep="0.001" inherit_timestep="true"/>
    <objects>
      <system typename="Subsystem" name="Ext" external_path="/etc/other.hmf"/>
    </objects>
    <connections/>
  </system>
</hopsanmodelfile>)";
    LoadedModel m = loadHmfString(hmf, "", "test");
    ASSERT_TRUE(m.hasErrors());
    EXPECT_NE(m.firstError().find("disabled"), std::string::npos) << m.firstError();
}
