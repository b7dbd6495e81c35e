#include "FeatureColour.h"

#include "SdfNoise.h"

#include <algorithm>
#include <cmath>

namespace tessera::creature {

namespace {

glm::vec3 mix(const glm::vec3& a, const glm::vec3& b, float t) { return a + (b - a) * t; }

glm::vec3 irisColour(float hue) {
    const glm::vec3 sulphur(0.86f, 0.74f, 0.14f), amber(0.85f, 0.44f, 0.07f), blood(0.66f, 0.09f, 0.05f);
    return hue < 0.5f ? mix(sulphur, amber, hue * 2.0f) : mix(amber, blood, hue * 2.0f - 1.0f);
}

} // namespace

glm::vec3 featureColour(const FeatureSample& f, const glm::vec3& p, const CreatureParams& c, const glm::vec3& skin) {
    const uint32_t seed = c.seed * 131u + 17u;
    glm::vec3 colour = skin;
    switch (f.surface) {
    case Surface::Skin:
        break;
    case Surface::Sclera: {
        // Yellowed, with red veins creeping in from the back of the ball.
        colour = glm::vec3(0.86f, 0.81f, 0.6f) * (1.0f - 0.35f * f.shade);
        float vein = noise::ridged(p * 700.0f, seed + 1u);
        colour = mix(colour, glm::vec3(0.72f, 0.25f, 0.18f), std::clamp(vein * vein * (0.2f + 0.6f * f.shade), 0.0f, 0.7f));
        break;
    }
    case Surface::Iris: {
        // Radial fibres, a darker rim and a lighter ring round the pupil.
        float fibres = noise::gradient(p * 1500.0f, seed + 2u);
        colour = irisColour(c.irisHue) * (0.85f + 0.2f * fibres);
        colour *= 1.0f - 0.65f * std::clamp((f.shade - 0.8f) * 5.0f, 0.0f, 1.0f);
        colour = mix(colour, glm::vec3(0.95f, 0.85f, 0.35f), 0.25f * std::clamp(1.0f - f.shade * 2.5f, 0.0f, 1.0f));
        break;
    }
    case Surface::Pupil:
        colour = glm::vec3(0.03f, 0.02f, 0.02f);
        break;
    case Surface::Lip:
        colour = mix(skin * 0.55f, glm::vec3(0.32f, 0.17f, 0.15f), 0.5f * (1.0f - f.shade));
        break;
    case Surface::Mouth:
        colour = glm::vec3(0.16f, 0.04f, 0.05f);
        break;
    case Surface::Tooth: {
        // Stained at the root, ivory towards the point.
        float t = std::clamp(f.shade / 0.7f, 0.0f, 1.0f);
        colour = mix(glm::vec3(0.58f, 0.47f, 0.28f), glm::vec3(0.9f, 0.85f, 0.68f), t * t * (3.0f - 2.0f * t));
        break;
    }
    case Surface::Leather: {
        glm::vec3 tan(0.5f, 0.32f, 0.16f), oxblood(0.3f, 0.12f, 0.09f);
        colour = mix(tan, oxblood, c.leatherHue) * (0.72f + 0.45f * f.shade);
        // Worn patches, lighter where it rubs.
        float wear = noise::fbm(p * 40.0f, seed + 3u, 2);
        colour *= 1.0f + 0.18f * wear;
        break;
    }
    case Surface::Stitch:
        colour = glm::vec3(0.76f, 0.7f, 0.52f);
        break;
    case Surface::Metal: {
        float tarnish = noise::fbm(p * 250.0f, seed + 4u, 2);
        colour = glm::vec3(0.66f, 0.5f, 0.24f) * (0.95f - 0.35f * std::abs(2.0f * f.shade - 1.0f));
        colour = mix(colour, glm::vec3(0.3f, 0.36f, 0.26f), std::clamp(0.5f * tarnish, 0.0f, 0.5f));
        break;
    }
    }
    return glm::clamp(colour, glm::vec3(0.0f), glm::vec3(1.0f));
}

} // namespace tessera::creature
