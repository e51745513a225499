#include "core/Model.h"

#include "core/SystemCopy.h"
#include "core/hmf/HmfSaver.h"

#include <utility>

namespace tlmhub {

Model::Model() : mRoot(std::make_unique<System>()) {}

Model::Model(std::unique_ptr<System> root) : mRoot(root ? std::move(root) : std::make_unique<System>()) {}

Result<Model> Model::copy() const
{
    Result<std::unique_ptr<System>> copied = copySystem(*mRoot);
    if (!copied) return copied.status();
    return Model(std::move(*copied));
}

std::string Model::toHmf() const { return saveHmfString(*mRoot); }

std::unique_ptr<System> Model::releaseRoot() { return std::exchange(mRoot, std::make_unique<System>()); }

} // namespace tlmhub
