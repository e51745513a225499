#include "server/jobs/ModelLimits.h"

#include "core/ParameterEvaluator.h"

namespace tlmhub::server {

LoadedModel loadUntrustedModel(const std::string& hmf, const ModelLimits& limits,
                               const std::string& modelDirectory, const std::string& sourceName)
{
    if (hmf.size() > limits.maxBytes) {
        LoadedModel refused;
        refused.messages.push_back({MessageType::Error,
                                    sourceName + ": the model is " + std::to_string(hmf.size()) +
                                        " bytes; the limit here is " + std::to_string(limits.maxBytes) +
                                        " (--max-model-bytes)",
                                    {}});
        return refused;
    }
    LoadLimits load;
    load.maxComponents = limits.maxComponents;
    load.componentsHint = " (--max-model-components)";
    load.maxSubsystemDepth = limits.maxDepth;
    load.depthHint = " (--max-model-depth)";
    return loadHmfString(hmf, modelDirectory, sourceName, load);
}

namespace {

std::string problemIn(System& system, const std::string& prefix)
{
    for (const auto& param : system.parameters().all())
        if (const Status evaluated = ParameterEvaluator::evaluate(system, *param); !evaluated)
            return "system parameter '" + prefix + param->name + "': " + evaluated.message();
    for (Component* c : system.componentsInOrder()) {
        if (c->isSystem()) {
            const std::string inner = problemIn(*static_cast<System*>(c), prefix + c->name() + "$");
            if (!inner.empty()) return inner;
            continue;
        }
        for (const auto& param : c->parameters().all())
            if (const Status evaluated = ParameterEvaluator::evaluate(*c, *param); !evaluated)
                return "parameter '" + prefix + c->name() + "." + param->name + "': " + evaluated.message();
    }
    return {};
}

} // namespace

std::string firstParameterProblem(System& root)
{
    return problemIn(root, "");
}

} // namespace tlmhub::server
