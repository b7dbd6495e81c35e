#include "SkeletonBuilder.h"

#define GLM_ENABLE_EXPERIMENTAL
#include <glm/gtc/type_ptr.hpp>
#include <glm/gtx/matrix_decompose.hpp>

namespace tessera::assets {

character::NodeTransform nodeTransform(const tinygltf::Node& node) {
    character::NodeTransform t;
    if (node.matrix.size() == 16) {
        glm::dmat4 m = glm::make_mat4(node.matrix.data());
        glm::dvec3 scale(1.0), translation(0.0), skew(0.0);
        glm::dquat rotation(1.0, 0.0, 0.0, 0.0);
        glm::dvec4 perspective(0.0, 0.0, 0.0, 1.0);
        glm::decompose(m, scale, rotation, translation, skew, perspective);
        t.translation = glm::vec3(translation);
        t.rotation = glm::normalize(glm::quat(rotation));
        t.scale = glm::vec3(scale);
        return t;
    }
    if (node.translation.size() == 3)
        t.translation = glm::vec3(static_cast<float>(node.translation[0]), static_cast<float>(node.translation[1]),
                                  static_cast<float>(node.translation[2]));
    if (node.rotation.size() == 4)
        t.rotation = glm::normalize(glm::quat(static_cast<float>(node.rotation[3]), static_cast<float>(node.rotation[0]),
                                              static_cast<float>(node.rotation[1]), static_cast<float>(node.rotation[2])));
    if (node.scale.size() == 3)
        t.scale = glm::vec3(static_cast<float>(node.scale[0]), static_cast<float>(node.scale[1]),
                            static_cast<float>(node.scale[2]));
    return t;
}

SkeletonBuild buildSkeleton(const tinygltf::Model& model) {
    std::vector<int> roots;
    int scene = model.defaultScene >= 0 ? model.defaultScene : (model.scenes.empty() ? -1 : 0);
    if (scene >= 0) {
        roots = model.scenes[static_cast<size_t>(scene)].nodes;
    } else {
        std::vector<bool> isChild(model.nodes.size(), false);
        for (const tinygltf::Node& n : model.nodes)
            for (int c : n.children) isChild[static_cast<size_t>(c)] = true;
        for (size_t i = 0; i < model.nodes.size(); ++i)
            if (!isChild[i]) roots.push_back(static_cast<int>(i));
    }
    SkeletonBuild build;
    // Depth-first with an explicit stack; the validators guarantee a forest.
    std::vector<std::pair<int, int32_t>> stack;
    for (auto it = roots.rbegin(); it != roots.rend(); ++it) stack.emplace_back(*it, -1);
    while (!stack.empty()) {
        auto [node, parent] = stack.back();
        stack.pop_back();
        const tinygltf::Node& n = model.nodes[static_cast<size_t>(node)];
        uint32_t index = static_cast<uint32_t>(build.skeleton.nodes.size());
        build.skeleton.nodes.push_back({n.name, parent, nodeTransform(n)});
        build.nodeToIndex[node] = index;
        build.indexToNode.push_back(node);
        for (auto c = n.children.rbegin(); c != n.children.rend(); ++c) stack.emplace_back(*c, static_cast<int32_t>(index));
    }
    return build;
}

} // namespace tessera::assets
