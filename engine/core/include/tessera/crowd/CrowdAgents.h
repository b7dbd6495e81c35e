#pragma once
/// @file CrowdAgents.h
/// The agents of a crowd, structure-of-arrays: what renderers and gameplay
/// read every frame.

#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace tessera::crowd {

/// The animation an agent plays; the renderer maps it to a clip of the model.
enum class AgentClip : uint8_t { Idle = 0, Walk = 1 };

/// One array per attribute, all of size(); index i of every array is agent i.
/// The crowd re-sorts agents in memory by where they stand every few steps,
/// so an index names an agent only until the next step; `id` is stable for
/// the crowd's lifetime (Crowd::indexOf finds it). Read-only for users:
/// Crowd changes it during step().
struct CrowdAgents {
    std::vector<glm::vec3> position;     ///< world metres; y on the terrain
    std::vector<glm::vec2> velocity;     ///< world XZ metres per second
    std::vector<float> heading;          ///< facing, radians about +Y (0 faces +Z)
    std::vector<float> radius;           ///< metres
    std::vector<float> preferredSpeed;   ///< metres per second on flat ground
    std::vector<uint16_t> goalGroup;     ///< index into the crowd's goal groups
    std::vector<AgentClip> clip;         ///< idle or walk
    std::vector<float> phase;            ///< position in the clip's cycle, [0, 1)
    std::vector<uint32_t> id;            ///< stable identifier

    size_t size() const { return position.size(); }
};

} // namespace tessera::crowd
