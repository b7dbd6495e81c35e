#pragma once
// The point type OpenSubdiv's templated refiners and stencil tables
// interpolate (they call Clear and AddWithWeight on it).

namespace tessera::subdiv::detail {

struct OsdPoint {
    float x = 0.0f, y = 0.0f, z = 0.0f;

    void Clear() { x = y = z = 0.0f; }
    void AddWithWeight(const OsdPoint& p, float w) {
        x += w * p.x;
        y += w * p.y;
        z += w * p.z;
    }
};

} // namespace tessera::subdiv::detail
