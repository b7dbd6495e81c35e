#include "CameraOrbit.h"

#include <algorithm>
#include <cmath>

namespace tessera::demo {

scene::CameraPose CameraOrbit::pose(const terrain::Terrain& terrain, double seconds) const {
    const float a = kStart + kSpeed * float(seconds);
    glm::vec3 position = site + glm::vec3(distance * std::sin(a), 0.0f, distance * std::cos(a));
    position.y = std::max(site.y + height, terrain.heightAt(position.x, position.z) + clearance);
    const glm::vec3 d = site + glm::vec3(0.0f, lookHeight, 0.0f) - position;
    scene::CameraPose pose;
    pose.position = position;
    pose.yaw = std::atan2(-d.x, -d.z);
    pose.pitch = std::atan2(d.y, std::sqrt(d.x * d.x + d.z * d.z));
    return pose;
}

} // namespace tessera::demo
