#include "GlbAssetCheck.h"

#include <cmath>

namespace tessera::creature {

namespace {

using character::AnimationInterpolation;
using character::TextureFormat;
using std::to_string;

template <class Vec>
bool finite(const Vec& v) {
    for (int i = 0; i < Vec::length(); ++i) {
        if (!std::isfinite(v[i])) return false;
    }
    return true;
}

Status checkCage(const character::CharacterAsset& asset, const std::string& file) {
    const character::CageMesh& cage = asset.cage;
    if (cage.vertices.empty() || cage.indices.empty()) return fail(file, ": the cage has no triangles");
    if (cage.indices.size() % 3 != 0) {
        return fail(file, ": the cage has ", to_string(cage.indices.size()), " indices, not a multiple of 3");
    }
    for (size_t i = 0; i < cage.indices.size(); ++i) {
        if (cage.indices[i] >= cage.vertices.size()) {
            return fail(file, ": cage index ", to_string(i), " (", to_string(cage.indices[i]), ") is beyond the ",
                        to_string(cage.vertices.size()), " vertices");
        }
    }
    for (size_t i = 0; i < cage.vertices.size(); ++i) {
        const character::CageVertex& v = cage.vertices[i];
        if (!finite(v.position) || !finite(v.normal) || !finite(v.tangent) || !finite(v.uv) || !finite(v.weights)) {
            return fail(file, ": cage vertex ", to_string(i), " has a non-finite value");
        }
        if (cage.bindings.empty()) continue;
        for (int c = 0; c < 4; ++c) {
            if (v.joints[c] >= cage.bindings.size()) {
                return fail(file, ": cage vertex ", to_string(i), " uses joint ", to_string(v.joints[c]),
                            " of a palette of ", to_string(cage.bindings.size()));
            }
        }
    }
    for (size_t b = 0; b < cage.bindings.size(); ++b) {
        const character::SkinBinding& binding = cage.bindings[b];
        if (binding.node >= asset.skeleton.nodes.size()) {
            return fail(file, ": skin binding ", to_string(b), " names node ", to_string(binding.node), " of ",
                        to_string(asset.skeleton.nodes.size()));
        }
        for (int c = 0; c < 4; ++c) {
            if (!finite(binding.inverseBind[c])) return fail(file, ": skin binding ", to_string(b), " is not finite");
        }
    }
    return {};
}

// The far mesh is drawn with the cage's palette: it must index it the same way.
Status checkFarMesh(const character::CharacterAsset& asset, const std::string& file) {
    if (!asset.farMesh) return {};
    const character::CageMesh& far = *asset.farMesh;
    if (far.vertices.empty() || far.indices.empty()) return fail(file, ": the far mesh has no triangles");
    if (far.indices.size() % 3 != 0) return fail(file, ": the far mesh's index count is not a multiple of 3");
    for (uint32_t i : far.indices) {
        if (i >= far.vertices.size()) return fail(file, ": a far mesh index is beyond its vertices");
    }
    if (far.bindings.size() != asset.cage.bindings.size()) return fail(file, ": the far mesh's palette differs from the cage's");
    for (size_t b = 0; b < far.bindings.size(); ++b) {
        if (far.bindings[b].node != asset.cage.bindings[b].node ||
            far.bindings[b].inverseBind != asset.cage.bindings[b].inverseBind)
            return fail(file, ": the far mesh's palette differs from the cage's at entry ", to_string(b));
    }
    for (size_t v = 0; v < far.vertices.size(); ++v) {
        const character::CageVertex& x = far.vertices[v];
        if (!finite(x.position) || !finite(x.normal) || !finite(x.tangent) || !finite(x.uv) || !finite(x.weights))
            return fail(file, ": far mesh vertex ", to_string(v), " has a non-finite value");
        for (int c = 0; c < 4; ++c) {
            if (!far.bindings.empty() && x.joints[c] >= far.bindings.size())
                return fail(file, ": far mesh vertex ", to_string(v), " uses joint ", to_string(x.joints[c]),
                            " of a palette of ", to_string(far.bindings.size()));
        }
    }
    return {};
}

Status checkClips(const character::CharacterAsset& asset, const std::string& file) {
    for (const character::AnimationClip& clip : asset.clips) {
        for (size_t c = 0; c < clip.channels.size(); ++c) {
            const character::AnimationChannel& channel = clip.channels[c];
            std::string where = file + ": clip '" + clip.name + "' channel " + to_string(c);
            if (channel.node >= asset.skeleton.nodes.size()) return fail(where, ": node ", to_string(channel.node), " does not exist");
            if (channel.times.empty()) return fail(where, ": no keys");
            for (size_t k = 0; k < channel.times.size(); ++k) {
                float t = channel.times[k];
                if (!std::isfinite(t) || t < 0.0f || (k > 0 && !(t > channel.times[k - 1]))) {
                    return fail(where, ": key time ", to_string(k), " is not a strictly increasing non-negative time");
                }
            }
            size_t perKey = channel.interpolation == AnimationInterpolation::CubicSpline ? 3 : 1;
            if (channel.values.size() != channel.times.size() * perKey) {
                return fail(where, ": ", to_string(channel.values.size()), " values for ", to_string(channel.times.size()),
                            " keys");
            }
            for (const glm::vec4& value : channel.values) {
                if (!finite(value)) return fail(where, ": a key value is not finite");
            }
        }
    }
    return {};
}

Status checkMaps(const character::CharacterAsset& asset, const std::string& file) {
    if (asset.baseColor && asset.baseColor->format != TextureFormat::Rgba8) {
        return fail(file, ": the base colour map must be RGBA8");
    }
    if (asset.normalMap && asset.normalMap->format != TextureFormat::Rgba8) {
        return fail(file, ": the normal map must be RGBA8");
    }
    if (asset.displacement) {
        if (asset.displacement->image.format != TextureFormat::R16) return fail(file, ": the displacement map must be R16");
        if (!std::isfinite(asset.displacement->scale) || !std::isfinite(asset.displacement->bias)) {
            return fail(file, ": the displacement scale or bias is not finite");
        }
    }
    return {};
}

} // namespace

Status checkCharacter(const character::CharacterAsset& asset, const std::string& file) {
    if (!asset.skeleton.isParentFirst()) return fail(file, ": skeleton nodes are not in parent-first order");
    for (size_t n = 0; n < asset.skeleton.nodes.size(); ++n) {
        const character::NodeTransform& rest = asset.skeleton.nodes[n].rest;
        if (!finite(rest.translation) || !finite(rest.rotation) || !finite(rest.scale)) {
            return fail(file, ": node ", to_string(n), " has a non-finite transform");
        }
    }
    if (Status s = checkCage(asset, file); !s) return s;
    if (Status s = checkFarMesh(asset, file); !s) return s;
    if (Status s = checkClips(asset, file); !s) return s;
    return checkMaps(asset, file);
}

} // namespace tessera::creature
