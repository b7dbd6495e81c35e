// The procedural creature: determinism, cage topology, atlas, skinning,
// sculpt envelope, skeleton and clips. Small options keep it fast.

#include "creature/CreatureGenerator.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sys/wait.h>
#include <map>
#include <tuple>

using namespace tessera;
using namespace tessera::creature;

namespace {

CreatureOptions smallOptions(uint32_t seed) {
    CreatureOptions o;
    o.seed = seed;
    o.sculptTriangles = 50'000;
    o.cageTriangles = 1'000;
    o.baseColorSize = 256;
    return o;
}

const Creature& generated(uint32_t seed) {
    static std::map<uint32_t, Creature> cache;
    auto it = cache.find(seed);
    if (it == cache.end()) it = cache.emplace(seed, generateCreature(smallOptions(seed))).first;
    return it->second;
}

using Key = std::tuple<float, float, float>;
Key key(const glm::vec3& p) { return {p.x, p.y, p.z}; }

float signedUvArea(const character::CageMesh& cage, size_t t) {
    glm::vec2 a = cage.vertices[cage.indices[t]].uv, b = cage.vertices[cage.indices[t + 1]].uv,
              c = cage.vertices[cage.indices[t + 2]].uv;
    return (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
}

float pointTriangleDistance(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    glm::vec3 n = glm::normalize(glm::cross(b - a, c - a));
    glm::vec3 q = p - n * glm::dot(p - a, n);
    bool inside = glm::dot(glm::cross(b - a, q - a), n) >= 0 && glm::dot(glm::cross(c - b, q - b), n) >= 0 &&
                  glm::dot(glm::cross(a - c, q - c), n) >= 0;
    if (inside) return std::abs(glm::dot(p - a, n));
    auto seg = [&](const glm::vec3& u, const glm::vec3& v) {
        float h = std::clamp(glm::dot(p - u, v - u) / glm::dot(v - u, v - u), 0.0f, 1.0f);
        return glm::length(p - u - (v - u) * h);
    };
    return std::min({seg(a, b), seg(b, c), seg(c, a)});
}

} // namespace

TEST(CreatureGenerator, SameSeedGivesIdenticalBytes) {
    Creature again = generateCreature(smallOptions(1));
    const Creature& first = generated(1);
    const auto& a = first.asset.cage;
    const auto& b = again.asset.cage;
    ASSERT_EQ(a.vertices.size(), b.vertices.size());
    EXPECT_EQ(0, std::memcmp(a.vertices.data(), b.vertices.data(), a.vertices.size() * sizeof(a.vertices[0])));
    EXPECT_EQ(a.indices, b.indices);
    ASSERT_EQ(first.sculpt.positions.size(), again.sculpt.positions.size());
    EXPECT_EQ(0, std::memcmp(first.sculpt.positions.data(), again.sculpt.positions.data(),
                             first.sculpt.positions.size() * sizeof(glm::vec3)));
    EXPECT_EQ(first.sculpt.indices, again.sculpt.indices);
    EXPECT_EQ(first.asset.baseColor->bytes, again.asset.baseColor->bytes);
}

TEST(CreatureGenerator, DistinctSeedsDiffer) {
    const auto& a = generated(1).sculpt;
    const auto& b = generated(2).sculpt;
    bool differ = a.positions.size() != b.positions.size() ||
                  std::memcmp(a.positions.data(), b.positions.data(), a.positions.size() * sizeof(glm::vec3)) != 0;
    EXPECT_TRUE(differ);
    glm::vec3 hiA(-1e9f), hiB(-1e9f);
    for (const auto& p : a.positions) hiA = glm::max(hiA, p);
    for (const auto& p : b.positions) hiB = glm::max(hiB, p);
    EXPECT_GT(glm::length(hiA - hiB), 0.005f) << "the two creatures have the same proportions";
}

// The default cage size, with a small sculpt and texture to stay fast.
const Creature& generatedDefaultCage(uint32_t seed) {
    static std::map<uint32_t, Creature> cache;
    auto it = cache.find(seed);
    if (it == cache.end()) {
        CreatureOptions o = smallOptions(seed);
        o.cageTriangles = 5'000;
        it = cache.emplace(seed, generateCreature(o)).first;
    }
    return it->second;
}

void expectClosedManifold(const character::CageMesh& cage) {
    // Weld the seam copies by position, then every directed edge must meet
    // its reverse exactly once.
    std::map<Key, uint32_t> weld;
    std::vector<uint32_t> id(cage.vertices.size());
    for (size_t i = 0; i < cage.vertices.size(); ++i)
        id[i] = weld.try_emplace(key(cage.vertices[i].position), static_cast<uint32_t>(weld.size())).first->second;
    std::map<std::pair<uint32_t, uint32_t>, int> edges;
    for (size_t t = 0; t < cage.indices.size(); t += 3)
        for (size_t k = 0; k < 3; ++k) {
            uint32_t from = id[cage.indices[t + k]], to = id[cage.indices[t + (k + 1) % 3]];
            ASSERT_NE(from, to) << "degenerate triangle " << t / 3;
            ++edges[{from, to}];
        }
    for (const auto& [edge, count] : edges) {
        ASSERT_EQ(count, 1) << "edge used twice in one direction";
        auto reverse = edges.find({edge.second, edge.first});
        ASSERT_TRUE(reverse != edges.end()) << "open edge";
    }
    // Euler characteristic 2: one closed genus-0 surface.
    long v = static_cast<long>(weld.size()), e = static_cast<long>(edges.size() / 2), f = cage.triangleCount();
    EXPECT_EQ(v - e + f, 2);
}

TEST(CreatureGenerator, CageIsClosedManifoldNearTarget) {
    EXPECT_NEAR(static_cast<double>(generated(1).asset.cage.triangleCount()), 1000.0, 100.0);
    expectClosedManifold(generated(1).asset.cage);
    EXPECT_NEAR(static_cast<double>(generatedDefaultCage(3).asset.cage.triangleCount()), 5000.0, 250.0);
    expectClosedManifold(generatedDefaultCage(3).asset.cage);
}

TEST(CreatureGenerator, SculptMeetsTargetAndStaysNearTheCage) {
    const Creature& c = generated(1);
    EXPECT_GE(c.sculpt.triangleCount(), 50'000u);
    const auto& cage = c.asset.cage;
    float worst = 0.0f;
    for (size_t i = 0; i < c.sculpt.positions.size(); i += 211) {
        const glm::vec3& p = c.sculpt.positions[i];
        float best = 1e9f;
        for (size_t t = 0; t < cage.indices.size(); t += 3)
            best = std::min(best, pointTriangleDistance(p, cage.vertices[cage.indices[t]].position,
                                                        cage.vertices[cage.indices[t + 1]].position,
                                                        cage.vertices[cage.indices[t + 2]].position));
        worst = std::max(worst, best);
    }
    // The baker's default envelopes are 5 cm each way.
    EXPECT_LT(worst, 0.04f);
}

void expectCleanAtlas(const character::CageMesh& cage) {
    for (const auto& v : cage.vertices) {
        EXPECT_GE(v.uv.x, 0.0f);
        EXPECT_LE(v.uv.x, 1.0f);
        EXPECT_GE(v.uv.y, 0.0f);
        EXPECT_LE(v.uv.y, 1.0f);
    }
    for (size_t t = 0; t < cage.indices.size(); t += 3) ASSERT_GT(signedUvArea(cage, t), 0.0f) << "flipped " << t / 3;

    // Overlap: no texel centre (at 2048) lies inside two triangles.
    const int size = 2048;
    std::vector<uint8_t> hits(static_cast<size_t>(size) * size, 0);
    size_t overlaps = 0;
    for (size_t t = 0; t < cage.indices.size(); t += 3) {
        glm::vec2 p[3];
        for (int k = 0; k < 3; ++k) p[k] = cage.vertices[cage.indices[t + static_cast<size_t>(k)]].uv * float(size);
        int x0 = std::max(0, int(std::floor(std::min({p[0].x, p[1].x, p[2].x}))));
        int x1 = std::min(size - 1, int(std::ceil(std::max({p[0].x, p[1].x, p[2].x}))));
        int y0 = std::max(0, int(std::floor(std::min({p[0].y, p[1].y, p[2].y}))));
        int y1 = std::min(size - 1, int(std::ceil(std::max({p[0].y, p[1].y, p[2].y}))));
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) {
                glm::vec2 q(x + 0.5f, y + 0.5f);
                bool inside = true;
                for (int k = 0; k < 3; ++k) {
                    glm::vec2 a = p[k], b = p[(k + 1) % 3];
                    // Strictly inside (a small margin) so shared edges never count twice.
                    float cross = (b.x - a.x) * (q.y - a.y) - (b.y - a.y) * (q.x - a.x);
                    if (cross <= 1e-3f * glm::length(b - a)) inside = false;
                }
                if (inside && hits[size_t(y) * size + size_t(x)]++) ++overlaps;
            }
    }
    EXPECT_EQ(overlaps, 0u);

    // Charts (connected through shared split vertices) keep >= 8 texels at
    // 2048 between their boxes.
    std::vector<uint32_t> parent(cage.vertices.size());
    for (uint32_t i = 0; i < parent.size(); ++i) parent[i] = i;
    auto find = [&](uint32_t x) { while (parent[x] != x) x = parent[x] = parent[parent[x]]; return x; };
    for (size_t t = 0; t < cage.indices.size(); t += 3)
        for (size_t k = 1; k < 3; ++k) parent[find(cage.indices[t + k])] = find(cage.indices[t]);
    std::map<uint32_t, std::pair<glm::vec2, glm::vec2>> boxes;
    for (uint32_t i = 0; i < cage.vertices.size(); ++i) {
        auto [it, fresh] = boxes.try_emplace(find(i), cage.vertices[i].uv, cage.vertices[i].uv);
        it->second.first = glm::min(it->second.first, cage.vertices[i].uv);
        it->second.second = glm::max(it->second.second, cage.vertices[i].uv);
    }
    EXPECT_GT(boxes.size(), 1u);
    for (auto a = boxes.begin(); a != boxes.end(); ++a)
        for (auto b = std::next(a); b != boxes.end(); ++b) {
            glm::vec2 gap = glm::max(b->second.first - a->second.second, a->second.first - b->second.second);
            EXPECT_GE(std::max(gap.x, gap.y) * 2048.0f, 8.0f - 1e-3f);
        }
}

TEST(CreatureGenerator, AtlasHasNoFlipsOverlapsOrNarrowGutters) {
    expectCleanAtlas(generated(1).asset.cage);
    expectCleanAtlas(generatedDefaultCage(3).asset.cage);
}

TEST(CreatureGenerator, SeamCopiesAgreeAndFramesAreOrthonormal) {
    const auto& cage = generated(1).asset.cage;
    std::map<Key, size_t> first;
    size_t seamCopies = 0;
    for (size_t i = 0; i < cage.vertices.size(); ++i) {
        const auto& v = cage.vertices[i];
        auto [it, fresh] = first.try_emplace(key(v.position), i);
        if (!fresh) {
            ++seamCopies;
            const auto& w = cage.vertices[it->second];
            EXPECT_EQ(v.normal, w.normal);
            EXPECT_EQ(v.joints, w.joints);
            EXPECT_EQ(v.weights, w.weights);
        }
        EXPECT_NEAR(glm::length(v.normal), 1.0f, 1e-4f);
        EXPECT_NEAR(glm::length(glm::vec3(v.tangent)), 1.0f, 1e-4f);
        EXPECT_NEAR(glm::dot(v.normal, glm::vec3(v.tangent)), 0.0f, 1e-4f);
        EXPECT_EQ(v.tangent.w, 1.0f);
    }
    EXPECT_GT(seamCopies, 0u);
}

TEST(CreatureGenerator, SkinWeightsAreNormalisedAndValid) {
    const auto& cage = generated(1).asset.cage;
    ASSERT_FALSE(cage.bindings.empty());
    for (const auto& v : cage.vertices) {
        float sum = v.weights.x + v.weights.y + v.weights.z + v.weights.w;
        EXPECT_NEAR(sum, 1.0f, 1e-5f);
        for (int k = 0; k < 4; ++k) {
            EXPECT_GE(v.weights[k], 0.0f);
            EXPECT_LT(v.joints[k], cage.bindings.size());
        }
    }
}

TEST(CreatureGenerator, SkeletonAndClips) {
    const auto& asset = generated(1).asset;
    EXPECT_TRUE(asset.skeleton.isParentFirst());
    EXPECT_GE(asset.skeleton.nodes.size(), 20u);
    // Bindings hold the inverse of each node's bind-pose global matrix.
    std::vector<glm::mat4> global(asset.skeleton.nodes.size());
    for (size_t i = 0; i < global.size(); ++i) {
        const auto& n = asset.skeleton.nodes[i];
        global[i] = n.parent < 0 ? n.rest.matrix() : global[size_t(n.parent)] * n.rest.matrix();
    }
    for (const auto& b : asset.cage.bindings) {
        glm::mat4 m = global[b.node] * b.inverseBind;
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) EXPECT_NEAR(m[c][r], c == r ? 1.0f : 0.0f, 1e-5f);
    }
    std::map<std::string, float> durations;
    for (const auto& clip : asset.clips) {
        durations[clip.name] = clip.duration();
        for (const auto& ch : clip.channels) {
            EXPECT_LT(ch.node, asset.skeleton.nodes.size());
            ASSERT_EQ(ch.times.size(), ch.values.size());
            for (size_t i = 1; i < ch.times.size(); ++i) EXPECT_GT(ch.times[i], ch.times[i - 1]);
            if (ch.path == character::AnimationPath::Rotation) {
                for (const auto& q : ch.values) EXPECT_NEAR(glm::length(q), 1.0f, 1e-5f);
            }
            // Loops close: the last key equals the first.
            EXPECT_LT(glm::length(ch.values.front() - ch.values.back()), 1e-3f);
        }
    }
    EXPECT_NEAR(durations["walk"], 1.1f, 1e-4f);
    EXPECT_NEAR(durations["idle"], 3.0f, 1e-4f);
}

TEST(CreatureGenerator, StandsOnTheGroundAtGoblinHeight) {
    const auto& cage = generated(2).asset.cage;
    glm::vec3 lo(1e9f), hi(-1e9f);
    for (const auto& v : cage.vertices) {
        lo = glm::min(lo, v.position);
        hi = glm::max(hi, v.position);
    }
    EXPECT_NEAR(lo.y, 0.0f, 0.005f);
    EXPECT_GT(hi.y, 1.0f);
    EXPECT_LT(hi.y, 1.35f);
    ASSERT_TRUE(generated(2).asset.baseColor.has_value());
    EXPECT_EQ(generated(2).asset.baseColor->width, 256u);
}

// The command-line tool, when it has been built beside the tests.
namespace {

struct ToolRun {
    int exitCode = -1;
    std::string output;
};

ToolRun runTool(const std::string& args) {
    ToolRun run;
    std::string command = std::string(TESSERA_BINARY_DIR) + "/bin/tessera-creaturegen " + args + " 2>&1";
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) return run;
    char buffer[512];
    while (fgets(buffer, sizeof buffer, pipe)) run.output += buffer;
    int status = pclose(pipe);
    run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return run;
}

bool toolBuilt() { return std::filesystem::exists(std::string(TESSERA_BINARY_DIR) + "/bin/tessera-creaturegen"); }

} // namespace

TEST(CreatureGenTool, BadFlagsFailWithOneLine) {
    if (!toolBuilt()) GTEST_SKIP() << "tessera-creaturegen not built";
    for (const char* args : {"--seed 1", "--seed x --out a.glb", "--out a.glb --map-size 4096",
                             "--out a.glb --cage-triangles", "--out a.glb --frobnicate 3", "--out a.glb --quiet=1"}) {
        ToolRun run = runTool(args);
        EXPECT_EQ(run.exitCode, 2) << args;
        EXPECT_EQ(std::count(run.output.begin(), run.output.end(), '\n'), 1) << args << ": " << run.output;
        EXPECT_EQ(run.output.rfind("tessera-creaturegen: ", 0), 0u) << run.output;
    }
}

TEST(CreatureGenTool, WritesGlbAndReport) {
    if (!toolBuilt()) GTEST_SKIP() << "tessera-creaturegen not built";
    std::filesystem::path dir = std::filesystem::path(TESSERA_TEST_OUTPUT_DIR) / "creaturegen";
    std::filesystem::create_directories(dir);
    ToolRun run = runTool("--seed 4 --out " + (dir / "tiny.glb").string() + " --report " + (dir / "tiny.json").string() +
                          " --map-size 128 --sculpt-triangles 20000 --cage-triangles 600 --quiet");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_TRUE(run.output.empty()) << run.output;
    EXPECT_GT(std::filesystem::file_size(dir / "tiny.glb"), 1000u);
    std::ifstream in(dir / "tiny.json");
    const nlohmann::json report = nlohmann::json::parse(in, nullptr, false);
    ASSERT_TRUE(report.is_object()) << "tiny.json is not a JSON object";
    for (const char* field : {"cage_bytes_draco", "cage_bytes_uncompressed", "displacement_map_bytes", "dense_mesh_bytes",
                              "misses", "sculpt_triangles"})
        EXPECT_TRUE(report.contains(field)) << field << " missing from " << report;
    EXPECT_EQ(report.value("displacement_map_bytes", 0), 32768);
}
