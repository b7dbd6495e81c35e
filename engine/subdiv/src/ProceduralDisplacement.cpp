#include "tessera/subdiv/ProceduralDisplacement.h"

#include "tessera/core/Random.h"

#include <cmath>
#include <numbers>

namespace tessera::subdiv {

ProceduralDisplacement::ProceduralDisplacement(const SubdivSurface& surface)
    : ProceduralDisplacement(surface, Settings{}) {}

ProceduralDisplacement::ProceduralDisplacement(const SubdivSurface& surface, const Settings& settings)
    : mSurface(&surface) {
    const scene::Aabb box = surface.bounds();
    mCentre = (glm::dvec3(box.min) + glm::dvec3(box.max)) * 0.5;
    const double diagonal = std::max(surface.boundsDiagonal(), 1e-12);
    // The core generator: the same waves on every platform.
    Random random(settings.seed);
    // Octave o: amplitude 2^-o, normalised so the waves' amplitudes sum to
    // the requested largest displacement.
    double total = 0.0;
    for (uint32_t o = 0; o < settings.octaves; ++o) total += settings.wavesPerOctave * std::ldexp(1.0, -int(o));
    for (uint32_t o = 0; o < settings.octaves; ++o)
        for (uint32_t w = 0; w < settings.wavesPerOctave; ++w) {
            // A uniform direction on the sphere.
            const double z = 2.0 * random.nextDouble() - 1.0, a = 2.0 * std::numbers::pi * random.nextDouble();
            const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
            const double frequency =
                2.0 * std::numbers::pi * settings.wavesPerDiagonal * std::ldexp(1.0, int(o)) / diagonal;
            Wave wave;
            wave.direction = glm::dvec3(r * std::cos(a), r * std::sin(a), z) * frequency;
            wave.phase = 2.0 * std::numbers::pi * random.nextDouble();
            wave.amplitude = settings.amplitude * diagonal * std::ldexp(1.0, -int(o)) / std::max(total, 1e-12);
            mWaves.push_back(wave);
        }
}

double ProceduralDisplacement::at(const glm::dvec3& position) const {
    const glm::dvec3 p = position - mCentre;
    double sum = 0.0;
    for (const Wave& wave : mWaves) sum += wave.amplitude * std::sin(glm::dot(wave.direction, p) + wave.phase);
    return sum;
}

double ProceduralDisplacement::operator()(uint32_t ptexFace, glm::dvec2 uv) const {
    const std::optional<LimitPoint> point = mSurface->evaluatePtex(ptexFace, uv);
    return point ? at(point->position) : 0.0;
}

DisplacementSampler ProceduralDisplacement::sampler() const {
    return [this](uint32_t ptexFace, glm::dvec2 uv) { return (*this)(ptexFace, uv); };
}

} // namespace tessera::subdiv
