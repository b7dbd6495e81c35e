#pragma once
/// @file ProceduralDisplacement.h
/// A displacement for shapes that come without one (`--model shape.obj`,
/// the tests): a sum of sinusoids of the base surface's limit position, so
/// it is smooth and continuous across tiles, whatever the ptex layout.
/// Feed it to convertDisplacement.

#include "tessera/subdiv/DisplacementConversion.h"
#include "tessera/subdiv/SubdivSurface.h"

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace tessera::subdiv {

class ProceduralDisplacement {
public:
    struct Settings {
        /// Largest displacement, as a fraction of the bounding-box diagonal.
        double amplitude = 0.02;
        /// Waves of the first octave along the diagonal; each further
        /// octave doubles it at half the amplitude.
        double wavesPerDiagonal = 3.0;
        uint32_t octaves = 3;
        uint32_t wavesPerOctave = 3;
        uint32_t seed = 1;
    };

    /// Keeps a reference to `surface`, which must outlive this.
    explicit ProceduralDisplacement(const SubdivSurface& surface);
    ProceduralDisplacement(const SubdivSurface& surface, const Settings& settings);

    /// The field at a point in space (object units).
    double at(const glm::dvec3& position) const;
    /// The field at the limit position of ptex face (u, v); 0 where there
    /// is no limit surface (holes).
    double operator()(uint32_t ptexFace, glm::dvec2 uv) const;
    /// This as a DisplacementSampler (referring to this object).
    DisplacementSampler sampler() const;

private:
    struct Wave {
        glm::dvec3 direction{1.0, 0.0, 0.0}; ///< times the angular frequency
        double phase = 0.0;
        double amplitude = 0.0;
    };

    const SubdivSurface* mSurface = nullptr;
    glm::dvec3 mCentre{0.0};
    std::vector<Wave> mWaves;
};

} // namespace tessera::subdiv
