#pragma once
// What a model that comes from a user may contain, and loading it within those bounds.
// The defaults admit every shared Hopsan model and the benchmark models (x200: 10 MB,
// 4001 components); a model past them is refused with an error naming the limit and its flag.
#include "core/hmf/HmfLoader.h"

#include <cstddef>
#include <string>

namespace tlmhub::server {

struct ModelLimits {
    std::size_t maxBytes = 16u << 20;      // .hmf text (--max-model-bytes)
    std::size_t maxComponents = 20000;     // components and subsystems (--max-model-components)
    std::size_t maxDepth = 16;             // subsystem nesting (--max-model-depth)
    std::size_t maxFmus = 64;              // imported FMUs, FMIWrapper components (--max-model-fmus)
};

// Loads `hmf` within `limits`; on refusal root is null and firstError() says why.
LoadedModel loadUntrustedModel(const std::string& hmf, const ModelLimits& limits,
                               const std::string& modelDirectory, const std::string& sourceName);

// The same limits for a model already in memory (an editor's), whose .hmf text is
// `hmfBytes` long: the first one it breaks, in the loader's words, or "".
std::string modelLimitProblem(const System& root, std::size_t hmfBytes, const ModelLimits& limits,
                              const std::string& sourceName);

// Evaluates every system and component parameter once (expressions, system parameter
// names), so a model that cannot run is refused when it is stored rather than at its first
// run. Returns the first problem, naming the parameter by path ("Sub$Comp.param"), or "".
std::string firstParameterProblem(System& root);

} // namespace tlmhub::server
