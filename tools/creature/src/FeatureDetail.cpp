#include "FeatureDetail.h"

#include "SdfNoise.h"

#include <algorithm>
#include <cmath>

namespace tessera::creature {

namespace {

// How far off a feature's shape a point may be and still count as on it:
// the sculpt and the texel centres sit within about a millimetre of the field.
constexpr float kOnShape = 0.0012f;

float smoothstep(float e0, float e1, float x) {
    float t = std::clamp((x - e0) / (e1 - e0), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

/// An arc-length coordinate around the band's axis, for stitch spacing.
/// `radius` is the band's typical distance from its centre.
float aroundBand(const GearBand& band, const glm::vec3& p, float radius) {
    glm::vec3 ref = std::abs(band.axis.x) < 0.9f ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 0.0f, 1.0f);
    glm::vec3 t1 = glm::normalize(glm::cross(band.axis, ref));
    glm::vec3 t2 = glm::cross(band.axis, t1);
    glm::vec3 d = p - band.centre;
    return std::atan2(glm::dot(d, t2), glm::dot(d, t1)) * radius;
}

} // namespace

FeatureDetail::FeatureDetail(const CreatureSdf& sdf, uint32_t seed) : mSdf(sdf), mSeed(seed * 2654435761u + 101u) {}

FeatureSample FeatureDetail::sample(const glm::vec3& p) const {
    FeatureSample s;
    if (sampleEye(p, s) || sampleMouth(p, s) || sampleGear(p, s)) return s;
    return s;
}

bool FeatureDetail::sampleEye(const glm::vec3& p, FeatureSample& out) const {
    for (const EyeLayout& eye : mSdf.layout().eyes) {
        glm::vec3 d = p - eye.centre;
        float r = glm::length(d);
        if (r > eye.radius * 1.6f) continue;
        if (r > eye.radius + kOnShape) {
            // The lids: smooth skin, no warts.
            out.skinMask = smoothstep(1.15f, 1.6f, r / eye.radius) * 0.7f + 0.3f;
            return false;
        }
        // Polar coordinates around the gaze: the iris is a disc of 0.58
        // radii (about 35 degrees), the pupil a vertical slit in it.
        glm::vec3 q = d / std::max(r, 1e-6f);
        glm::vec3 right = glm::normalize(glm::cross(glm::vec3(0.0f, 1.0f, 0.0f), eye.gaze));
        glm::vec3 up = glm::cross(eye.gaze, right);
        float u = glm::dot(q, right), v = glm::dot(q, up);
        float rho = std::sqrt(u * u + v * v);
        out.skinMask = 0.0f;
        out.displacement = 0.0f;
        if (glm::dot(q, eye.gaze) > 0.0f && rho < 0.58f) {
            float slit = (u / 0.1f) * (u / 0.1f) + (v / 0.42f) * (v / 0.42f);
            out.surface = slit < 1.0f ? Surface::Pupil : Surface::Iris;
            out.shade = rho / 0.58f;
        } else {
            out.surface = Surface::Sclera;
            out.shade = std::clamp(-glm::dot(q, eye.gaze), 0.0f, 1.0f);
        }
        return true;
    }
    return false;
}

bool FeatureDetail::sampleMouth(const glm::vec3& p, FeatureSample& out) const {
    const FeatureLayout& layout = mSdf.layout();
    for (const CapsuleLayout& tooth : layout.teeth) {
        if (capsuleDistance(tooth, p) < kOnShape) {
            out = {Surface::Tooth, 0.0f, 0.0f, 0.0f};
            glm::vec3 ab = tooth.b - tooth.a;
            out.shade = std::clamp(glm::dot(p - tooth.a, ab) / glm::dot(ab, ab), 0.0f, 1.0f);
            return true;
        }
    }
    for (const CapsuleLayout& tusk : layout.tusks) {
        if (capsuleDistance(tusk, p) < kOnShape) {
            out = {Surface::Tooth, 0.0f, 0.0f, 0.0f};
            glm::vec3 ab = tusk.b - tusk.a;
            float along = std::clamp(glm::dot(p - tusk.a, ab) / glm::dot(ab, ab), 0.0f, 1.0f);
            // Growth rings across the tusk, faint ridges a millimetre apart.
            out.displacement = 0.00015f * std::sin(along * glm::length(ab) * 6000.0f);
            out.shade = along;
            return true;
        }
    }
    float slit = std::min(capsuleDistance(layout.mouthSlit[0], p), capsuleDistance(layout.mouthSlit[1], p));
    // Inside the carved groove: the dark of the mouth. Around it: the lips,
    // smooth and a little swollen towards the groove.
    if (slit > -kOnShape && slit < kOnShape) {
        out = {Surface::Mouth, 0.0f, 0.0f, 0.0f};
        return true;
    }
    if (slit < 0.006f) {
        out = {Surface::Lip, 0.25f, 0.0008f * (1.0f - smoothstep(0.0f, 0.006f, slit)), slit / 0.006f};
        return true;
    }
    return false;
}

bool FeatureDetail::sampleGear(const glm::vec3& p, FeatureSample& out) const {
    const std::vector<GearBand>& bands = mSdf.layout().bands;
    // Later bands lie over earlier ones (the strap over the belt).
    for (size_t i = bands.size(); i-- > 0;) {
        const GearBand& band = bands[i];
        float region = bandRegion(band, p);
        if (region > 0.0005f) continue;
        // On the band's face the covered shape is `thickness` below; on
        // its sides, between 0 and that. Limbs crossing the band's plane
        // (added after it) are further off or nearer, so they stay skin.
        float under = mSdf.distanceBefore(p, band.primitive);
        if (under < -0.002f || under > band.thickness + 0.003f) continue;
        if (band.kind == GearBand::Kind::Belt && buckle(band, p, out)) return true;
        leather(band, p, std::max(0.0f, -region), out);
        return true;
    }
    return false;
}

void FeatureDetail::leather(const GearBand& band, const glm::vec3& p, float inside, FeatureSample& out) const {
    out.surface = Surface::Leather;
    out.skinMask = 0.0f;
    // Rounded, slightly worn edges.
    float relief = -0.0006f * (1.0f - smoothstep(0.0f, 0.002f, inside));
    // Grain: fine pores and a few longer creases.
    float grain = noise::fbm(p * 420.0f, mSeed + 3u, 2);
    float crease = noise::ridged(p * glm::vec3(90.0f, 160.0f, 90.0f), mSeed + 5u);
    relief += 0.00018f * grain - 0.00035f * crease * crease;
    out.shade = std::clamp(0.5f + 0.5f * grain - 0.3f * crease, 0.0f, 1.0f);
    // Saddle stitching: a sunk row 4.5 mm in from each edge (just past the bevel), with a raised
    // thread every 6 mm (4 mm of thread, 2 mm of hole).
    float row = std::abs(inside - 0.0045f);
    if (row < 0.0009f) {
        float radius = band.kind == GearBand::Kind::Bracer ? 0.045f : 0.16f;
        float phase = aroundBand(band, p, radius) / 0.006f;
        phase -= std::floor(phase);
        if (phase < 0.66f) {
            float across = 1.0f - row / 0.0009f;
            relief = -0.0002f + 0.00045f * std::sqrt(std::max(across, 0.0f));
            out.surface = Surface::Stitch;
        } else {
            relief = -0.0006f;
        }
    }
    out.displacement = relief;
}

bool FeatureDetail::buckle(const GearBand& belt, const glm::vec3& p, FeatureSample& out) const {
    const FeatureLayout& layout = mSdf.layout();
    glm::vec3 d = p - layout.buckleCentre;
    if (glm::dot(d, layout.buckleNormal) < -0.03f) return false;  // the back of the belt
    glm::vec3 across = glm::normalize(glm::cross(belt.axis, layout.buckleNormal));
    float u = std::abs(glm::dot(d, across)), v = std::abs(glm::dot(d, belt.axis));
    const float outerU = 0.021f, outerV = belt.halfWidth - 0.001f;
    if (u > outerU || v > outerV) return false;
    const float innerU = 0.012f, innerV = outerV - 0.0065f;
    out.surface = Surface::Metal;
    out.skinMask = 0.0f;
    if (u > innerU || v > innerV) {
        // The frame: a rounded bar, highest along its middle.
        float bu = u > innerU ? (u - innerU) / (outerU - innerU) : 0.0f;
        float bv = v > innerV ? (v - innerV) / (outerV - innerV) : 0.0f;
        float t = std::max(bu, bv);
        out.displacement = 0.0008f + 0.0022f * std::sqrt(std::max(0.0f, 1.0f - (2.0f * t - 1.0f) * (2.0f * t - 1.0f)));
        out.shade = t;
        return true;
    }
    // Inside the frame: the belt's tongue with the prong over it.
    glm::vec3 signedAcross = glm::normalize(glm::cross(belt.axis, layout.buckleNormal));
    float su = glm::dot(d, signedAcross);
    if (v < 0.0016f && su > -innerU && su < 0.004f) {
        out.displacement = 0.0018f * std::sqrt(std::max(0.0f, 1.0f - (v / 0.0016f) * (v / 0.0016f)));
        out.shade = 0.5f;
        return true;
    }
    out.surface = Surface::Leather;
    out.displacement = -0.0004f;
    out.shade = 0.2f;
    return true;
}

} // namespace tessera::creature
