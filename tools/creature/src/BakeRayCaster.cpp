#include "BakeRayCaster.h"

#include "tessera/core/ParallelFor.h"

#include <algorithm>
#include <cmath>

namespace tessera::creature {

std::vector<glm::vec3> sculptVertexNormals(const SculptMesh& sculpt) {
    std::vector<glm::vec3> normals(sculpt.positions.size(), glm::vec3(0.0f));
    for (uint32_t t = 0; t < sculpt.triangleCount(); ++t) {
        uint32_t i0 = sculpt.indices[3 * t], i1 = sculpt.indices[3 * t + 1], i2 = sculpt.indices[3 * t + 2];
        // The unnormalised cross product weighs each face by twice its area.
        glm::vec3 n = glm::cross(sculpt.positions[i1] - sculpt.positions[i0],
                                 sculpt.positions[i2] - sculpt.positions[i0]);
        normals[i0] += n;
        normals[i1] += n;
        normals[i2] += n;
    }
    for (glm::vec3& n : normals) {
        float len = glm::length(n);
        n = len > 0.0f ? n / len : glm::vec3(0.0f, 0.0f, 1.0f);
    }
    return normals;
}

namespace {

struct TexelContext {
    const character::CageMesh& cage;
    const UvRasterizer& raster;
    const Bvh& bvh;
    const SculptMesh& sculpt;
    const std::vector<glm::vec3>& sculptNormals;
    float inner, outer;
    BakedTexels& out;
};

/// Casts from the cage point (triangle, b1, b2); false on a miss.
bool castFrom(const TexelContext& c, int32_t triangle, float b1, float b2, float& displacement,
              glm::vec3* tangentNormal) {
    const character::CageVertex& v0 = c.cage.vertices[c.cage.indices[3 * triangle]];
    const character::CageVertex& v1 = c.cage.vertices[c.cage.indices[3 * triangle + 1]];
    const character::CageVertex& v2 = c.cage.vertices[c.cage.indices[3 * triangle + 2]];
    const float b0 = 1.0f - b1 - b2;
    // Exactly the renderer's evaluation of the interpolating planar subdivision.
    glm::vec3 position = b0 * v0.position + b1 * v1.position + b2 * v2.position;
    glm::vec3 n = b0 * v0.normal + b1 * v1.normal + b2 * v2.normal;
    float len = glm::length(n);
    glm::vec3 normal = len > 0.0f ? n / len : glm::vec3(0.0f, 0.0f, 1.0f);

    std::optional<BvhHit> hit = c.bvh.nearestHit(position, normal, -c.inner, c.outer, 0.0f);
    if (!hit) return false;
    displacement = hit->t;
    if (!tangentNormal) return true;

    const uint32_t* tri = &c.sculpt.indices[3 * hit->triangle];
    glm::vec3 sn = (1.0f - hit->u - hit->v) * c.sculptNormals[tri[0]] + hit->u * c.sculptNormals[tri[1]] +
                   hit->v * c.sculptNormals[tri[2]];
    float snLen = glm::length(sn);
    sn = snLen > 0.0f ? sn / snLen : normal;

    // The cage tangent frame the normal map is expressed in (documented in
    // DisplacementBaker.h): N, T Gram-Schmidt against N, B = w * cross(N, T).
    glm::vec3 t = b0 * glm::vec3(v0.tangent) + b1 * glm::vec3(v1.tangent) + b2 * glm::vec3(v2.tangent);
    t -= normal * glm::dot(normal, t);
    float tLen = glm::length(t);
    if (!(tLen > 1e-12f)) {
        // Degenerate tangent: any frame keeps the texel defined.
        t = std::fabs(normal.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
        t = glm::normalize(t - normal * glm::dot(normal, t));
    } else {
        t /= tLen;
    }
    float w = b0 * v0.tangent.w + b1 * v1.tangent.w + b2 * v2.tangent.w;
    glm::vec3 b = (w < 0.0f ? -1.0f : 1.0f) * glm::cross(normal, t);
    *tangentNormal = {glm::dot(sn, t), glm::dot(sn, b), glm::dot(sn, normal)};
    return true;
}

void bakeTexel(const TexelContext& c, uint32_t index) {
    const TexelSample& s = c.raster.at(index);
    if (s.kind == TexelKind::Empty) return;
    bool hit = castFrom(c, s.triangle, s.b1, s.b2, c.out.displacement[index], &c.out.normal[index]);
    if (!hit) {
        // A ray through a sculpt vertex or edge can slip between the
        // triangles there by rounding (chart corners cast exactly from cage
        // vertices); retry a hair towards the triangle's centre.
        const float k = 1e-4f;
        hit = castFrom(c, s.triangle, s.b1 * (1.0f - k) + k / 3.0f, s.b2 * (1.0f - k) + k / 3.0f,
                       c.out.displacement[index], &c.out.normal[index]);
    }
    c.out.state[index] = hit ? TexelState::Hit : TexelState::Miss;
}

/// Turns a Dilated texel's value at Q into the linear extrapolation to its centre.
void extrapolateTexel(const TexelContext& c, const DilatedTexel& d) {
    if (c.out.state[d.index] != TexelState::Hit || d.ratio == 0.0f) return;
    float inner;
    if (!castFrom(c, c.raster.at(d.index).triangle, d.m1, d.m2, inner, nullptr)) return;
    // Kept inside the envelope: a texel never claims more than a ray could see.
    float& value = c.out.displacement[d.index];
    float extrapolated = value + (value - inner) * d.ratio;
    if (std::isfinite(extrapolated)) value = std::clamp(extrapolated, -c.inner, c.outer);
}

} // namespace

BakedTexels castTexelRays(const character::CageMesh& cage, const UvRasterizer& raster, const Bvh& bvh,
                          const SculptMesh& sculpt, const std::vector<glm::vec3>& sculptNormals,
                          float inner, float outer, uint32_t threads,
                          const std::function<void(float)>& progress) {
    const uint32_t size = raster.size();
    const size_t count = static_cast<size_t>(size) * size;
    BakedTexels out;
    out.displacement.assign(count, 0.0f);
    out.normal.assign(count, glm::vec3(0.0f, 0.0f, 1.0f));
    out.state.assign(count, TexelState::Unbaked);
    TexelContext context{cage, raster, bvh, sculpt, sculptNormals, inner, outer, out};

    core::parallelFor(
        size, threads,
        [&](uint32_t row) {
            for (uint32_t x = 0; x < size; ++x) bakeTexel(context, row * size + x);
        },
        [&](uint32_t rowsDone) {
            if (progress) progress(static_cast<float>(rowsDone) / static_cast<float>(size));
        });
    // After all rows: each extrapolation only reads and writes its own texel.
    for (const DilatedTexel& d : raster.dilatedTexels()) extrapolateTexel(context, d);

    for (TexelState state : out.state) out.misses += state == TexelState::Miss ? 1 : 0;
    return out;
}

} // namespace tessera::creature
