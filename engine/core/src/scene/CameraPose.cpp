#include "tessera/scene/CameraPose.h"

#include <charconv>
#include <system_error>

namespace tessera::scene {

std::string formatCameraPose(const CameraPose& pose) {
    const float values[] = {pose.position.x, pose.position.y, pose.position.z, glm::degrees(pose.yaw),
                            glm::degrees(pose.pitch)};
    std::string out;
    for (size_t i = 0; i < 5; ++i) {
        // to_chars gives the shortest text that reads back to the same float,
        // independent of locale.
        char buffer[32];
        auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, values[i]);
        if (i > 0) out.push_back(',');
        out.append(buffer, ec == std::errc{} ? end : buffer);
    }
    return out;
}

} // namespace tessera::scene
