#pragma once
/// @file StrideLength.h
/// How much ground a walk clip covers per cycle, measured from the clip
/// itself: what a crowd needs to advance an agent's clip phase by distance
/// travelled / stride length, so that its feet do not slide.
///
/// A planted foot stays still on the ground while the body passes over it,
/// so relative to the hips it moves backward at exactly the body's speed. The
/// measurement poses the skeleton (Pose) over one clip duration, finds the
/// feet, keeps the samples where each foot is at the bottom of its lift (its
/// stance) and takes the median of its backward speed relative to the hips
/// there. Measuring against the hips makes in-place clips and clips with root
/// motion give the same figure. The method and the figures for the generated
/// creatures and CesiumMan are in docs/CHARACTERS.md ("Stride length").

#include "tessera/character/CharacterAsset.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace tessera::character {

/// What measureStride found for one clip.
struct StrideMeasure {
    float strideLength = 0.0f;   ///< model units of ground per clip cycle at playback speed 1 (0 when the clip does not walk)
    float naturalSpeed = 0.0f;   ///< strideLength / clip duration: the speed at which feet do not slide
    std::vector<uint32_t> feet;  ///< skeleton nodes used as feet
};

/// Measures how far a body must travel per cycle of `clip` so that its feet
/// do not slide: the clip's stride length and its natural speed, in the
/// asset's world units (the node transforms above the skeleton's joints, such
/// as a root's scale or its Z-up to Y-up rotation, are included), assuming
/// glTF's +Y up. A cycle is the clip's duration() as Pose plays it.
///
/// - **Feet.** Candidates are the skin's joints (every node when the cage
///   has no skin bindings). First the joints whose names contain "foot",
///   "ankle" or "toe" (any case): the one nearest the skeleton's root (an
///   ankle before its toe, then the lower), and its partner on another leg
///   (the candidate whose common ancestor with it is nearest the root, then
///   nearest the root itself). Without such a pair, the lowest leaf joint in
///   the rest pose and its partner on another leg, both within the lowest
///   quarter of the skeleton's height (so a foot is not paired with a hand).
///   Two feet never lie one above the other in the hierarchy and stand at
///   least 2% of the skeleton's size apart. Without a pair, a single named
///   foot with a parent is used alone; otherwise `feet` is empty and the
///   result is 0.
/// - **Hips.** The feet's nearest common ancestor. Foot positions are taken
///   relative to it, so a clip in place and the same clip with root motion
///   (on the hips or above) measure the same.
/// - **Samples.** `samples` + 1 poses (`samples` at least 8) at uniform
///   times from 0 to the duration inclusive, without looping; velocities by
///   central differences (one-sided at the ends).
/// - **Stance.** The samples where the foot's world height is within 15% of
///   its vertical range above its lowest point (at least its 3 lowest), and
///   where it moves backward relative to the hips: a planted foot cannot
///   move forward under a body that walks forward.
/// - **Forward.** The horizontal direction opposite the feet's summed
///   velocity relative to the hips over the low samples. glTF models face
///   +Z, but the direction is measured, not assumed, so a model facing
///   elsewhere or a clip walking backwards measures too.
/// - **Speed.** For each foot that walks, the median over its stance samples
///   of its backward horizontal speed relative to the hips, along forward;
///   averaged over the feet. strideLength = naturalSpeed * duration.
///
/// A foot walks when it lifts by at least 1% of its leg length (the
/// rest-pose bone lengths from the hips down to it) and sweeps at least 5% of
/// it horizontally relative to the hips. A clip whose feet do not walk (an
/// idle, a march on the spot), a clip whose low feet never move backward, an
/// empty clip, or a `clip` index out of range gives 0, with `feet` still
/// filled when the skeleton has them. The skeleton must be parent-first
/// (Skeleton::isParentFirst); otherwise the result is empty.
///
/// A clip whose feet never plant (their backward speed still changes while
/// they are low, as in a procedural walk without foot locking) has no speed
/// at which nothing slides; the figure is then the median of the low
/// samples, and depends on the 15% band (docs/CHARACTERS.md).
StrideMeasure measureStride(const CharacterAsset& asset, size_t clip, uint32_t samples = 120);

} // namespace tessera::character
