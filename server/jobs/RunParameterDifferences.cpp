#include "server/jobs/RunParameterDifferences.h"

#include "core/ParameterTexts.h"

namespace tlmhub::server {

RunParameterDifferences::RunParameterDifferences(std::function<std::string()> currentHmf, ModelLimits limits)
    : mCurrentHmf(std::move(currentHmf)), mLimits(limits)
{
}

const RunParameterDifferences::Texts& RunParameterDifferences::textsOf(const std::string& hmf)
{
    auto found = mTextsByHmf.find(hmf);
    if (found != mTextsByHmf.end()) return found->second;
    const LoadedModel loaded = loadUntrustedModel(hmf, mLimits, "", "a run's model");
    Texts texts = loaded.root ? parameterTexts(*loaded.root) : Texts{};
    return mTextsByHmf.emplace(hmf, std::move(texts)).first->second;
}

RunParameterDifferences::Texts RunParameterDifferences::usedBy(const JobRequest& run)
{
    Texts used = textsOf(run.hmf);
    // An override names a parameter as findParameter does: "Comp.x" may mean the start value
    // "Comp.x#Value".
    for (const auto& [path, value] : run.parameters) {
        if (!used.count(path) && used.count(path + "#Value")) used[path + "#Value"] = value;
        else used[path] = value;
    }
    return used;
}

RunParameterDifferences::Texts RunParameterDifferences::differing(const Texts& used, std::size_t maxEntries,
                                                                  bool& truncated)
{
    if (!mCurrent) mCurrent = &textsOf(mCurrentHmf());
    Texts out;
    truncated = false;
    for (const auto& [path, value] : used) {
        const auto now = mCurrent->find(path);
        if (now != mCurrent->end() && now->second == value) continue;
        if (out.size() == maxEntries) {
            truncated = true;
            break;
        }
        out.emplace(path, value);
    }
    return out;
}

} // namespace tlmhub::server
