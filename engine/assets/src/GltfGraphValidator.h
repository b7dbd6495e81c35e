#pragma once
// GltfGraphValidator: the node graph and what hangs on it. Node trees
// (no loops, one parent, scenes list roots, matrices decomposable, unit
// rotations), skins (joint roots, skeleton, inverse bind matrices),
// animations (targets, sampler formats and counts) and image/texture types.

#include "GltfLayoutValidator.h"

#include <vector>

namespace tessera::assets {

class GltfGraphValidator {
public:
    GltfGraphValidator(const JsonChecker& json, GltfLayoutValidator& layout) : mJson(json), mLayout(layout) {}

    void validate();

private:
    void checkNodes();
    void checkNodeTransform(const Json& node, const std::string& ptr) const;
    void checkSkins();
    void checkAnimations();
    void checkImages();
    size_t rootOf(size_t node) const;
    size_t morphTargetCount(const Json& node) const;

    const JsonChecker& mJson;
    GltfLayoutValidator& mLayout;
    std::vector<int64_t> mParent;
};

} // namespace tessera::assets
