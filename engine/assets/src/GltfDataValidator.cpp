#include "GltfDataValidator.h"

#include "GltfError.h"
#include "GltfFormats.h"

#include "tessera/core/ImageFile.h"

#include <cmath>
#include <cstring>
#include <set>

namespace tessera::assets {

namespace {

std::string accessorPtr(int a) { return "/accessors/" + std::to_string(a); }

bool near(double a, double b, double tolerance) { return std::fabs(a - b) <= tolerance; }

// Accessors with no data in the file (implicit zeros, Draco output) carry no values to judge.
bool hasData(const nlohmann::json& json, int accessor) {
    const nlohmann::json& a = json["accessors"][static_cast<size_t>(accessor)];
    return a.contains("bufferView") || a.contains("sparse");
}

} // namespace

void GltfDataValidator::validate() const {
    checkAccessorBounds();
    checkPrimitives();
    checkAnimations();
    checkSkins();
    checkImages();
}

void GltfDataValidator::checkAccessorBounds() const {
    for (size_t i = 0; i < mModel.accessors.size(); ++i) {
        const tinygltf::Accessor& a = mModel.accessors[i];
        const nlohmann::json& ja = mJson["accessors"][i];
        // Accessors without a view in the file are zeros or Draco output (checked by Draco itself).
        if (!ja.contains("bufferView") && !ja.contains("sparse")) continue;
        std::vector<double> values = mReader.read(static_cast<int>(i), false);
        uint32_t n = mReader.components(static_cast<int>(i));
        for (size_t v = 0; v < values.size(); ++v)
            if (!std::isfinite(values[v]))
                raise(accessorPtr(static_cast<int>(i)), "element " + std::to_string(v / n) + " is not a finite number");
        for (const char* key : {"min", "max"}) {
            if (!ja.contains(key)) continue;
            bool isMin = key[1] == 'i';
            for (uint32_t c = 0; c < n; ++c) {
                double actual = isMin ? INFINITY : -INFINITY;
                for (size_t e = c; e < values.size(); e += n)
                    actual = isMin ? std::min(actual, values[e]) : std::max(actual, values[e]);
                double declared = ja[key][c].get<double>();
                if (a.componentType == kFloat) declared = static_cast<float>(declared);
                double tolerance = 1e-6 * std::max(1.0, std::fabs(declared));
                if (!near(actual, declared, tolerance))
                    raise(accessorPtr(static_cast<int>(i)) + "/" + key + "/" + std::to_string(c),
                          std::string("declared ") + key + " " + ja[key][c].dump() + " does not match the actual " +
                              std::to_string(actual));
            }
        }
    }
}

void GltfDataValidator::checkPrimitives() const {
    for (size_t m = 0; m < mModel.meshes.size(); ++m)
        for (size_t p = 0; p < mModel.meshes[m].primitives.size(); ++p) {
            const tinygltf::Primitive& prim = mModel.meshes[m].primitives[p];
            std::string ptr = "/meshes/" + std::to_string(m) + "/primitives/" + std::to_string(p);
            auto position = prim.attributes.find("POSITION");
            if (position == prim.attributes.end()) continue;
            size_t vertices = mModel.accessors[static_cast<size_t>(position->second)].count;
            if (prim.indices >= 0) {
                const tinygltf::Accessor& ia = mModel.accessors[static_cast<size_t>(prim.indices)];
                double restart = ia.componentType == kUnsignedByte ? 255.0 : ia.componentType == kUnsignedShort ? 65535.0 : 4294967295.0;
                std::vector<double> indices = mReader.read(prim.indices, false);
                for (size_t i = 0; i < indices.size(); ++i) {
                    if (indices[i] == restart) raise(ptr + "/indices", "index " + std::to_string(i) + " is the primitive restart value");
                    if (indices[i] >= static_cast<double>(vertices))
                        raise(ptr + "/indices", "index value " + std::to_string(static_cast<uint64_t>(indices[i])) +
                                                    " is not less than the vertex count " + std::to_string(vertices));
                }
            }
            for (const auto& [name, accessor] : prim.attributes) {
                if (!hasData(mJson, accessor)) continue;
                std::string ap = ptr + "/attributes/" + name;
                std::vector<double> v = mReader.read(accessor, true);
                if (name == "NORMAL" || name == "TANGENT") {
                    size_t n = name == "NORMAL" ? 3 : 4;
                    // Quantized vectors round each component to 1/127 or 1/32767.
                    double tolerance = mModel.accessors[static_cast<size_t>(accessor)].componentType == kFloat ? 5e-3 : 2.5e-2;
                    for (size_t e = 0; e + n <= v.size(); e += n) {
                        double len = std::sqrt(v[e] * v[e] + v[e + 1] * v[e + 1] + v[e + 2] * v[e + 2]);
                        if (!near(len, 1.0, tolerance)) raise(ap, "vector " + std::to_string(e / n) + " is not of unit length");
                        if (n == 4 && std::fabs(v[e + 3]) != 1.0) raise(ap, "tangent w must be 1 or -1");
                    }
                } else if (name.rfind("COLOR_", 0) == 0) {
                    for (double c : v)
                        if (c < 0.0 || c > 1.0) raise(ap, "colour value is not within 0..1");
                } else if (name.rfind("WEIGHTS_", 0) == 0) {
                    for (double w : v)
                        if (w < 0.0) raise(ap, "negative weight");
                }
            }
            // Weights over all sets sum to one; joints with weight are distinct and inside the skin.
            std::vector<double> sums(vertices, 0.0);
            std::vector<std::vector<std::pair<double, double>>> influences(vertices);
            for (int set = 0;; ++set) {
                auto w = prim.attributes.find("WEIGHTS_" + std::to_string(set));
                auto j = prim.attributes.find("JOINTS_" + std::to_string(set));
                if (w == prim.attributes.end() || j == prim.attributes.end()) break;
                if (!hasData(mJson, w->second) || !hasData(mJson, j->second)) {
                    influences.assign(vertices, {});
                    sums.assign(vertices, 1.0);
                    break;
                }
                std::vector<double> weights = mReader.read(w->second, true), joints = mReader.read(j->second, false);
                for (size_t e = 0; e < vertices && e * 4 + 3 < weights.size() && e * 4 + 3 < joints.size(); ++e)
                    for (size_t c = 0; c < 4; ++c) {
                        sums[e] += weights[e * 4 + c];
                        influences[e].emplace_back(joints[e * 4 + c], weights[e * 4 + c]);
                    }
            }
            if (prim.attributes.count("WEIGHTS_0"))
                for (size_t e = 0; e < vertices; ++e) {
                    if (!near(sums[e], 1.0, 2e-2)) raise(ptr + "/attributes/WEIGHTS_0", "weights of vertex " + std::to_string(e) + " are not normalized");
                    std::set<double> used;
                    for (auto [joint, weight] : influences[e])
                        if (weight > 0.0 && !used.insert(joint).second)
                            raise(ptr + "/attributes/JOINTS_0", "vertex " + std::to_string(e) + " uses a joint twice");
                }
            // Joint indices against every skin that skins this mesh.
            for (const tinygltf::Node& node : mModel.nodes) {
                if (node.mesh != static_cast<int>(m) || node.skin < 0) continue;
                double jointCount = static_cast<double>(mModel.skins[static_cast<size_t>(node.skin)].joints.size());
                for (const auto& list : influences)
                    for (auto [joint, weight] : list)
                        if (joint >= jointCount) raise(ptr + "/attributes/JOINTS_0", "joint index " + std::to_string(static_cast<int>(joint)) + " is outside the skin");
            }
        }
}

void GltfDataValidator::checkAnimations() const {
    for (size_t an = 0; an < mModel.animations.size(); ++an) {
        const tinygltf::Animation& animation = mModel.animations[an];
        for (size_t s = 0; s < animation.samplers.size(); ++s) {
            std::string sp = "/animations/" + std::to_string(an) + "/samplers/" + std::to_string(s);
            const nlohmann::json& input = mJson["accessors"][static_cast<size_t>(animation.samplers[s].input)];
            if (!input.contains("bufferView") && !input.contains("sparse")) continue;  // zeros: nothing to order
            std::vector<double> times = mReader.read(animation.samplers[s].input, false);
            for (size_t i = 0; i < times.size(); ++i) {
                if (times[i] < 0.0) raise(sp + "/input", "key time " + std::to_string(times[i]) + " is negative");
                if (i > 0 && times[i] <= times[i - 1]) raise(sp + "/input", "key times must be strictly increasing");
            }
        }
        for (const tinygltf::AnimationChannel& channel : animation.channels) {
            if (channel.target_path != "rotation") continue;
            const tinygltf::AnimationSampler& sampler = animation.samplers[static_cast<size_t>(channel.sampler)];
            if (!hasData(mJson, sampler.output)) continue;
            std::vector<double> q = mReader.read(sampler.output, true);
            bool cubic = sampler.interpolation == "CUBICSPLINE";
            for (size_t e = 0; e + 4 <= q.size(); e += 4) {
                if (cubic && (e / 4) % 3 != 1) continue;  // tangents need not be unit
                double len = std::sqrt(q[e] * q[e] + q[e + 1] * q[e + 1] + q[e + 2] * q[e + 2] + q[e + 3] * q[e + 3]);
                if (!near(len, 1.0, 5e-3))
                    raise("/animations/" + std::to_string(an), "rotation output " + std::to_string(e / 4) + " is not a unit quaternion");
            }
        }
    }
}

void GltfDataValidator::checkSkins() const {
    for (size_t s = 0; s < mModel.skins.size(); ++s) {
        if (mModel.skins[s].inverseBindMatrices < 0 || !hasData(mJson, mModel.skins[s].inverseBindMatrices)) continue;
        std::vector<double> m = mReader.read(mModel.skins[s].inverseBindMatrices, false);
        for (size_t e = 0; e + 16 <= m.size(); e += 16)
            if (m[e + 3] != 0.0 || m[e + 7] != 0.0 || m[e + 11] != 0.0 || m[e + 15] != 1.0)
                raise("/skins/" + std::to_string(s) + "/inverseBindMatrices",
                      "matrix " + std::to_string(e / 16) + " is not affine (last row must be 0 0 0 1)");
    }
}

void GltfDataValidator::checkImages() const {
    for (size_t i = 0; i < mModel.images.size(); ++i) {
        const tinygltf::Image& image = mModel.images[i];
        std::string ptr = "/images/" + std::to_string(i);
        const std::vector<unsigned char>& b = image.image;
        static const unsigned char png[] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
        std::string found = b.size() >= 8 && std::memcmp(b.data(), png, 8) == 0        ? "image/png"
                            : b.size() >= 3 && b[0] == 0xFF && b[1] == 0xD8 && b[2] == 0xFF ? "image/jpeg"
                            : b.size() >= 12 && std::memcmp(b.data(), "RIFF", 4) == 0 &&
                                      std::memcmp(b.data() + 8, "WEBP", 4) == 0       ? "image/webp"
                                                                                       : "";
        std::string declared = mJson["images"][i].value("mimeType", std::string());
        if (declared.empty() && mJson["images"][i].contains("uri")) {
            std::string uri = mJson["images"][i]["uri"].get<std::string>();
            if (uri.rfind("data:", 0) == 0) declared = uri.substr(5, uri.find_first_of(";,") - 5);
        }
        if (found.empty()) raise(ptr, "image data is not PNG, JPEG or WebP");
        if (!declared.empty() && declared != found)
            raise(ptr, "image data is " + found + " but the declared type is " + declared);
        if (found == "image/webp") continue;
        if (auto header = readImageHeader(b); !header)
            raise(ptr, "invalid image data (" + header.error().message + ")");
    }
}

} // namespace tessera::assets
