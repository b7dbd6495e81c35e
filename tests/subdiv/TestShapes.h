#pragma once
// Control meshes built in code for the subdivision tests: each exercises one
// feature (closed mesh with extraordinary vertices, open boundary, non-quads,
// an interior extraordinary vertex, creases, holes, corners).

#include "tessera/subdiv/ObjShape.h"

#include <cmath>
#include <initializer_list>
#include <numbers>
#include <string>
#include <vector>

namespace tessera::subdiv::test {

inline void addFace(ObjShape& shape, std::initializer_list<uint32_t> vertices) {
    shape.faceSizes.push_back(uint32_t(vertices.size()));
    shape.faceVertices.insert(shape.faceVertices.end(), vertices.begin(), vertices.end());
}

/// The unit cube: eight valence-3 extraordinary vertices.
inline ObjShape cube() {
    ObjShape s;
    s.name = "cube";
    s.positions = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}};
    addFace(s, {0, 3, 2, 1}); // bottom
    addFace(s, {4, 5, 6, 7}); // top
    addFace(s, {0, 1, 5, 4});
    addFace(s, {1, 2, 6, 5});
    addFace(s, {2, 3, 7, 6});
    addFace(s, {3, 0, 4, 7});
    return s;
}

/// An n x n grid of quads in the xy plane with a bump, open on all sides.
inline ObjShape grid(uint32_t n, BoundaryInterpolation boundary, const std::string& name) {
    ObjShape s;
    s.name = name;
    s.boundary = boundary;
    for (uint32_t j = 0; j <= n; ++j)
        for (uint32_t i = 0; i <= n; ++i) {
            float x = float(i) / float(n) * 2.0f - 1.0f, y = float(j) / float(n) * 2.0f - 1.0f;
            s.positions.push_back({x, y, 0.4f * std::cos(1.3f * x) * std::cos(1.7f * y) + 0.1f * x * y});
        }
    for (uint32_t j = 0; j < n; ++j)
        for (uint32_t i = 0; i < n; ++i) {
            uint32_t a = j * (n + 1) + i;
            addFace(s, {a, a + 1, a + n + 2, a + n + 1});
        }
    return s;
}

/// A pentagonal pyramid: one pentagon and five triangles, apex of valence 5.
inline ObjShape pentagonPyramid(bool smoothTriangles) {
    ObjShape s;
    s.name = smoothTriangles ? "pentagon_pyramid_smoothtris" : "pentagon_pyramid";
    s.smoothTriangles = smoothTriangles;
    for (int i = 0; i < 5; ++i) {
        double a = 2.0 * std::numbers::pi * i / 5.0;
        s.positions.push_back({float(std::cos(a)), float(std::sin(a)), float(0.1 * (i % 2))});
    }
    s.positions.push_back({0.1f, -0.05f, 1.3f});
    addFace(s, {4, 3, 2, 1, 0});
    for (uint32_t i = 0; i < 5; ++i) addFace(s, {i, (i + 1) % 5, 5});
    return s;
}

/// A disk around an interior valence-5 vertex (with valence-3 interior
/// vertices on the next ring) and an open boundary.
inline ObjShape extraordinaryDisk() {
    ObjShape s;
    s.name = "extraordinary_disk";
    const auto at = [](double radius, double degrees, double z) {
        double a = degrees * std::numbers::pi / 180.0;
        return glm::vec3(float(radius * std::cos(a)), float(radius * std::sin(a)), float(z));
    };
    s.positions.push_back({0.0f, 0.0f, 0.5f});                                             // 0: centre
    for (int i = 0; i < 5; ++i) s.positions.push_back(at(1.0, 72.0 * i, 0.2));             // 1..5: a_i
    for (int i = 0; i < 5; ++i) s.positions.push_back(at(1.1, 72.0 * i + 36.0, 0.3));      // 6..10: b_i
    for (int i = 0; i < 10; ++i) s.positions.push_back(at(2.2, 36.0 * i, -0.1 * (i % 3))); // 11..20: o_i
    for (uint32_t i = 0; i < 5; ++i) {
        uint32_t a = 1 + i, an = 1 + (i + 1) % 5, b = 6 + i;
        uint32_t o0 = 11 + 2 * i, o1 = 11 + 2 * i + 1, o2 = 11 + (2 * i + 2) % 10;
        addFace(s, {0, a, b, an});
        addFace(s, {a, o0, o1, b});
        addFace(s, {b, o1, o2, an});
    }
    return s;
}

/// A torus of `around` x `across` quads (every vertex regular), optionally
/// with a crease of `sharpness` around ring 0 (the loop of vertices
/// 0 .. around-1).
inline ObjShape torus(uint32_t around, uint32_t across, float sharpness, const std::string& name) {
    ObjShape s;
    s.name = name;
    for (uint32_t j = 0; j < across; ++j)
        for (uint32_t i = 0; i < around; ++i) {
            double a = 2.0 * std::numbers::pi * i / around, b = 2.0 * std::numbers::pi * j / across;
            double r = 2.0 + 0.7 * std::cos(b) + 0.05 * std::sin(3.0 * a);
            s.positions.push_back({float(r * std::cos(a)), float(r * std::sin(a)), float(0.7 * std::sin(b))});
        }
    const auto vertex = [&](uint32_t i, uint32_t j) { return (j % across) * around + (i % around); };
    for (uint32_t j = 0; j < across; ++j)
        for (uint32_t i = 0; i < around; ++i)
            addFace(s, {vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1), vertex(i, j + 1)});
    if (sharpness > 0.0f)
        for (uint32_t i = 0; i < around; ++i) s.creases.push_back({vertex(i, 0), vertex(i + 1, 0), sharpness});
    return s;
}

/// The cube with the loop of edges around its top face creased.
inline ObjShape creasedCube(float sharpness) {
    ObjShape s = cube();
    s.name = "cube_crease_" + std::to_string(int(sharpness));
    s.creases = {{4, 5, sharpness}, {5, 6, sharpness}, {6, 7, sharpness}, {7, 4, sharpness}};
    return s;
}

/// The cube with one face (the top, face 1) a hole.
inline ObjShape cubeWithHole() {
    ObjShape s = cube();
    s.name = "cube_hole";
    s.holes = {1};
    return s;
}

/// A grid with smooth boundary corners (EdgeOnly) and two sharp corners.
inline ObjShape gridWithCorners() {
    ObjShape s = grid(3, BoundaryInterpolation::EdgeOnly, "grid_corners");
    s.corners = {{0, 10.0f}, {5, 2.5f}};
    return s;
}

/// Every in-code shape.
inline std::vector<ObjShape> codeShapes() {
    return {cube(),
            grid(4, BoundaryInterpolation::EdgeAndCorner, "grid_edge_and_corner"),
            grid(3, BoundaryInterpolation::EdgeOnly, "grid_edge_only"),
            pentagonPyramid(false),
            pentagonPyramid(true),
            extraordinaryDisk(),
            torus(8, 6, 10.0f, "torus_sharp_ring"),
            torus(8, 6, 1.5f, "torus_semisharp_ring"),
            creasedCube(10.0f),
            creasedCube(2.0f),
            cubeWithHole(),
            gridWithCorners()};
}

} // namespace tessera::subdiv::test
