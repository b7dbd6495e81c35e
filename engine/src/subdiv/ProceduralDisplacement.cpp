#include "tessera/subdiv/ProceduralDisplacement.h"

#include <cmath>
#include <numbers>

namespace tessera::subdiv {

namespace {

// SplitMix64: the same waves on every platform (std's distributions are not
// specified bit for bit).
double nextUnit(uint64_t& state) {
    uint64_t z = (state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    z ^= z >> 31;
    return double(z >> 11) * 0x1.0p-53;
}

} // namespace

ProceduralDisplacement::ProceduralDisplacement(const SubdivSurface& surface)
    : ProceduralDisplacement(surface, Settings{}) {}

ProceduralDisplacement::ProceduralDisplacement(const SubdivSurface& surface, const Settings& settings)
    : mSurface(&surface) {
    const scene::Aabb box = surface.bounds();
    mCentre = (glm::dvec3(box.min) + glm::dvec3(box.max)) * 0.5;
    const double diagonal = std::max(surface.boundsDiagonal(), 1e-12);
    uint64_t state = settings.seed;
    // Octave o: amplitude 2^-o, normalised so the waves' amplitudes sum to
    // the requested largest displacement.
    double total = 0.0;
    for (uint32_t o = 0; o < settings.octaves; ++o) total += settings.wavesPerOctave * std::ldexp(1.0, -int(o));
    for (uint32_t o = 0; o < settings.octaves; ++o)
        for (uint32_t w = 0; w < settings.wavesPerOctave; ++w) {
            // A uniform direction on the sphere.
            const double z = 2.0 * nextUnit(state) - 1.0, a = 2.0 * std::numbers::pi * nextUnit(state);
            const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
            const double frequency =
                2.0 * std::numbers::pi * settings.wavesPerDiagonal * std::ldexp(1.0, int(o)) / diagonal;
            Wave wave;
            wave.direction = glm::dvec3(r * std::cos(a), r * std::sin(a), z) * frequency;
            wave.phase = 2.0 * std::numbers::pi * nextUnit(state);
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
