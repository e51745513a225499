#pragma once
// What a run of a model used that the model no longer says: for a model's run history (GET
// /jobs?model_id=), the value of each parameter the run used (its model text then, with the
// job's overrides) where it differs from the model's current text. A parameter the model has
// since lost is listed too; one it has gained is not (the run knew nothing of it).
#include "server/jobs/Job.h"
#include "server/jobs/ModelLimits.h"

#include <functional>
#include <map>
#include <string>
#include <unordered_map>

namespace tlmhub::server {

class RunParameterDifferences {
public:
    using Texts = std::map<std::string, std::string>;

    // `currentHmf` gives the model's text now; it is loaded at the first comparison.
    RunParameterDifferences(std::function<std::string()> currentHmf, ModelLimits limits);

    // The values of `used` that differ from the model now, at most `maxEntries` (the first by
    // path); `truncated` tells whether more differ.
    Texts differing(const Texts& used, std::size_t maxEntries, bool& truncated);

    // What a run used, from its stored request, for a job stored before the job kept it
    // (JobRequest::usedParameters): its model text with its overrides. Empty when that text no
    // longer loads.
    Texts usedBy(const JobRequest& run);

private:
    // Each model text loaded once per page: a model's runs mostly share it.
    const Texts& textsOf(const std::string& hmf);

    std::function<std::string()> mCurrentHmf;
    const ModelLimits mLimits;
    std::unordered_map<std::string, Texts> mTextsByHmf;
    const Texts* mCurrent = nullptr;
};

} // namespace tlmhub::server
