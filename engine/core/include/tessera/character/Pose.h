#pragma once
/// @file Pose.h
/// One animated state of a skeleton: local transforms sampled from clips,
/// global matrices and the skinning palette (the paper's first pass, on the
/// CPU; the GPU skinning pass is checked against it).

#include "tessera/character/AnimationClip.h"
#include "tessera/character/CageMesh.h"
#include "tessera/character/Skeleton.h"

#include <glm/glm.hpp>
#include <span>
#include <vector>

namespace tessera::character {

/// Local and global transforms of every node of one skeleton.
///
/// Typical use per frame: reset(); apply(clip, seconds); computeGlobals();
/// palette(cage, matrices). The skeleton must outlive the pose.
class Pose {
public:
    /// A pose at rest, globals computed. The skeleton must be parent-first.
    explicit Pose(const Skeleton& skeleton);

    /// Sets every local transform to the node's rest transform (globals are
    /// stale until computeGlobals()).
    void reset();

    /// Samples every channel of `clip` at `seconds` onto the local
    /// transforms (see sampleChannel). With `loop`, time wraps modulo the
    /// clip's duration; without, it clamps to [0, duration]. Properties no
    /// channel drives keep their current value, so call reset() first to
    /// start from rest. Channels naming a node outside the skeleton, or
    /// without usable keys, are skipped.
    void apply(const AnimationClip& clip, float seconds, bool loop = true);

    /// Global matrices: global(n) = global(parent(n)) * local(n).matrix(),
    /// in one parent-first pass.
    void computeGlobals();

    /// The local transform of `node` (for procedural animation or tests).
    NodeTransform& local(uint32_t node) { return mLocals[node]; }
    std::span<const NodeTransform> locals() const { return mLocals; }
    /// Global matrices as of the last computeGlobals().
    std::span<const glm::mat4> globals() const { return mGlobals; }

    /// The skinning palette of `cage`: out[i] = global(bindings[i].node) *
    /// bindings[i].inverseBind. Asserts every binding's node is in range.
    void palette(const CageMesh& cage, std::vector<glm::mat4>& out) const;

private:
    const Skeleton* mSkeleton;
    std::vector<NodeTransform> mLocals;
    std::vector<glm::mat4> mGlobals;
};

} // namespace tessera::character
