#pragma once
// Loading Hopsan model files (.hmf, versions 0.1-0.4) into a System (core.md §6).
#include "core/System.h"

#include <memory>
#include <string>
#include <vector>

namespace tlmhub {

struct LoadedModel {
    std::unique_ptr<System> root;
    std::vector<Message> messages;   // errors, warnings, info produced while loading
    bool hasErrors() const;
    std::string firstError() const;
    // Ok, or the first error: unknown_component_type for a type no library has, else
    // invalid_model (not a model file, a broken element or connection, a load limit).
    Status status() const;
};

// Bounds on what one model file may contain. Loading walks subsystems recursively, so the
// nesting depth is always bounded; a server tightens both limits for untrusted uploads.
struct LoadLimits {
    std::size_t maxSubsystemDepth = 64;   // subsystems inside subsystems, the root is level 0
    std::size_t maxComponents = 0;        // components and subsystems in all; 0: no limit
    // Components that load an external definition (imported FMUs) in all; 0: no limit.
    std::size_t maxExternalDefinitions = 0;
    // Appended to the refusal when the limit is hit, to say how it is raised (a server
    // names its flag, e.g. " (--max-model-depth)").
    std::string depthHint;
    std::string componentsHint;
    std::string externalDefinitionsHint;
};
// Elements nested deeper than this are refused before anything is built (no model needs
// more than a few dozen levels; every walk over the tree then stays shallow).
inline constexpr std::size_t kMaxXmlDepth = 512;

// Load a model from a file. Never throws; a broken file gives root == nullptr and an error
// message naming the file, the element and the reason.
LoadedModel loadHmfFile(const std::string& path, const LoadLimits& limits = {});
// Load from XML text; `modelDirectory` resolves relative paths (external subsystems, data).
LoadedModel loadHmfString(const std::string& xml, const std::string& modelDirectory,
                          const std::string& sourceName = "<string>", const LoadLimits& limits = {});

} // namespace tlmhub
