#include "server/jobs/ModelLimits.h"

#include "core/ParameterEvaluator.h"

namespace tlmhub::server {

namespace {

std::string sizeProblem(std::size_t hmfBytes, const ModelLimits& limits, const std::string& sourceName)
{
    if (hmfBytes <= limits.maxBytes) return {};
    return sourceName + ": the model is " + std::to_string(hmfBytes) + " bytes; the limit here is " +
           std::to_string(limits.maxBytes) + " (--max-model-bytes)";
}

LoadLimits loadLimits(const ModelLimits& limits)
{
    LoadLimits load;
    load.maxComponents = limits.maxComponents;
    load.componentsHint = " (--max-model-components)";
    load.maxSubsystemDepth = limits.maxDepth;
    load.depthHint = " (--max-model-depth)";
    load.maxExternalDefinitions = limits.maxFmus;
    load.externalDefinitionsHint = " (--max-model-fmus)";
    return load;
}

struct StructureCount {
    std::size_t components = 0, externalDefinitions = 0;
};

// Counts components and subsystems below `system` into `count`; the first limit broken.
std::string structureProblem(const System& system, std::size_t depth, const LoadLimits& limits, StructureCount& count)
{
    for (const Component* c : system.componentsInOrder()) {
        if (limits.maxComponents && ++count.components > limits.maxComponents)
            return "the model has more than " + std::to_string(limits.maxComponents) +
                   " components and subsystems, the limit here" + limits.componentsHint;
        if (c->loadsExternalDefinition() && limits.maxExternalDefinitions &&
            ++count.externalDefinitions > limits.maxExternalDefinitions)
            return "the model has more than " + std::to_string(limits.maxExternalDefinitions) + " " + c->typeName() +
                   " components (each loads a file), the limit here" + limits.externalDefinitionsHint;
        if (!c->isSystem()) continue;
        if (depth + 1 > limits.maxSubsystemDepth)
            return "subsystem '" + c->name() + "' is nested " + std::to_string(depth + 1) +
                   " levels deep; the limit is " + std::to_string(limits.maxSubsystemDepth) + limits.depthHint;
        const std::string inner = structureProblem(static_cast<const System&>(*c), depth + 1, limits, count);
        if (!inner.empty()) return inner;
    }
    return {};
}

} // namespace

LoadedModel loadUntrustedModel(const std::string& hmf, const ModelLimits& limits,
                               const std::string& modelDirectory, const std::string& sourceName)
{
    if (std::string tooLarge = sizeProblem(hmf.size(), limits, sourceName); !tooLarge.empty()) {
        LoadedModel refused;
        refused.messages.push_back({MessageType::Error, std::move(tooLarge), {}});
        return refused;
    }
    return loadHmfString(hmf, modelDirectory, sourceName, loadLimits(limits));
}

std::string modelLimitProblem(const System& root, std::size_t hmfBytes, const ModelLimits& limits,
                              const std::string& sourceName)
{
    if (std::string tooLarge = sizeProblem(hmfBytes, limits, sourceName); !tooLarge.empty()) return tooLarge;
    StructureCount count;
    return structureProblem(root, 0, loadLimits(limits), count);
}

namespace {

std::string problemIn(System& system, const std::string& prefix, ParameterEvaluator::Pass& pass)
{
    for (const auto& param : system.parameters().all())
        if (const Status evaluated = ParameterEvaluator::evaluate(system, *param, pass); !evaluated)
            return "system parameter '" + prefix + param->name + "': " + evaluated.message();
    for (Component* c : system.componentsInOrder()) {
        if (c->isSystem()) {
            const std::string inner = problemIn(*static_cast<System*>(c), prefix + c->name() + "$", pass);
            if (!inner.empty()) return inner;
            continue;
        }
        for (const auto& param : c->parameters().all())
            if (const Status evaluated = ParameterEvaluator::evaluate(*c, *param, pass); !evaluated)
                return "parameter '" + prefix + c->name() + "." + param->name + "': " + evaluated.message();
    }
    return {};
}

} // namespace

std::string firstParameterProblem(System& root)
{
    ParameterEvaluator::Pass pass;
    std::string problem = problemIn(root, "", pass);
    if (!problem.empty() && pass.evaluations >= pass.budget) problem += " (--max-parameter-evaluations)";
    return problem;
}

} // namespace tlmhub::server
