#include "tessera/cli/CameraPoseText.h"

#include "tessera/cli/NumberList.h"

#include <glm/trigonometric.hpp>

namespace tessera::cli {

Result<scene::CameraPose> parseCameraPose(std::string_view text, std::string_view flag) {
    const ListForm form{std::string(flag), "x,y,z,yaw,pitch (5 numbers)", {"x", "y", "z", "yaw", "pitch"}, 5, 5};
    auto values = parseNumberList<float>(text, form);
    if (!values) return values.error();
    const std::vector<float>& v = values.value();
    scene::CameraPose pose;
    pose.position = glm::vec3(v[0], v[1], v[2]);
    pose.yaw = glm::radians(v[3]);
    pose.pitch = glm::radians(v[4]);
    return pose;
}

} // namespace tessera::cli
