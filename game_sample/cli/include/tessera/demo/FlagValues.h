#pragma once
/// @file FlagValues.h
/// tessera-demo's flag values that are more than one number or word (lists,
/// colours, craters, ranges), each read by the command line's one list
/// reader (tessera/cli/NumberList.h) with an error that names the flag and
/// shows what was given.

#include "tessera/core/Result.h"
#include "tessera/terrain/CraterSplat.h"

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

namespace tessera::demo {

/// A Catmull-Clark control mesh (.obj, any case), not a glTF model.
bool isObjFile(const std::string& path);
/// --agents: one count, or a comma list of counts for --bench crowd and crowd-sim.
Result<std::vector<uint32_t>> parseAgents(const std::string& text);
/// --clear-color r,g,b, each in [0,1].
Result<glm::vec3> parseColor(const std::string& text);
/// --sun AZ,EL: the unit vector towards a sun at azimuth AZ (degrees from +X
/// towards +Z) and elevation EL (1 to 90 degrees).
Result<glm::vec3> parseSun(const std::string& text);
/// --splat x,z,radius[,depth] in metres.
Result<terrain::CraterSplat> parseSplat(const std::string& text);
/// `flag`'s "A" or "A:B" (a value, or a sweep from A to B over the run),
/// each a number in [lo, hi].
Result<std::pair<float, std::optional<float>>> parseSweep(const std::string& flag, const std::string& text, float lo,
                                                         float hi);

} // namespace tessera::demo
