#include "tessera/runtime/CameraOrbit.h"

#include <algorithm>
#include <cmath>

namespace tessera::runtime {

scene::CameraPose CameraOrbit::pose(const terrain::Terrain& terrain, double seconds) const {
    const float a = kStart + kSpeed * float(seconds);
    float radius = distance, rise = height, above = clearance;
    if (dollySeconds > 0.0) {
        radius = distance + (endDistance - distance) * float(std::clamp(seconds / dollySeconds, 0.0, 1.0));
        rise = height * radius / distance;
        above = clearance * radius / distance;
    }
    glm::vec3 position = site + glm::vec3(radius * std::sin(a), 0.0f, radius * std::cos(a));
    position.y = std::max(site.y + rise, terrain.heightAt(position.x, position.z) + above);
    const glm::vec3 d = site + glm::vec3(0.0f, lookHeight, 0.0f) - position;
    scene::CameraPose pose;
    pose.position = position;
    pose.yaw = std::atan2(-d.x, -d.z);
    pose.pitch = std::atan2(d.y, std::sqrt(d.x * d.x + d.z * d.z));
    return pose;
}

} // namespace tessera::runtime
