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
};

// Load a model from a file. Never throws; a broken file gives root == nullptr and an error
// message naming the file, the element and the reason.
LoadedModel loadHmfFile(const std::string& path);
// Load from XML text; `modelDirectory` resolves relative paths (external subsystems, data).
LoadedModel loadHmfString(const std::string& xml, const std::string& modelDirectory,
                          const std::string& sourceName = "<string>");

} // namespace tlmhub
