#pragma once
// The base colour of the close-up features (internal header).

#include "FeatureDetail.h"
#include "creature/CreatureParams.h"

#include <glm/glm.hpp>

namespace tessera::creature {

/// The colour (sRGB, 0..1) of a feature's surface at p: yellowed sclera,
/// an iris from yellow to red by `irisHue` with a dark slit pupil and rim,
/// dark lips and mouth, stained ivory teeth, leather by `leatherHue` with
/// pale stitching and a bronze buckle. `skin` is the skin's colour there,
/// which the lips darken.
glm::vec3 featureColour(const FeatureSample& feature, const glm::vec3& p, const CreatureParams& params,
                        const glm::vec3& skin);

} // namespace tessera::creature
