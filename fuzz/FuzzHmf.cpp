// Fuzzes .hmf loading (loadHmfString) and the model check that evaluates every parameter.
// Seeds: the shared Hopsan models, passed as extra corpus directories (scripts/fuzz.sh).
#include "core/hmf/HmfLoader.h"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string xml(reinterpret_cast<const char*>(data), size);
    // External subsystems resolve against a directory without models, so nothing outside
    // the input is read.
    tlmhub::LoadedModel model = tlmhub::loadHmfString(xml, "/nonexistent", "fuzz.hmf");
    if (model.root) model.root->check();
    return 0;
}
