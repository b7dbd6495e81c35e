#include "SkinDetail.h"

#include "SdfNoise.h"

#include <algorithm>
#include <cmath>

namespace tessera::creature {

SkinDetail::SkinDetail(const CreatureParams& c, const CreatureSdf& sdf)
    : mSeed(c.seed * 7919u + 13u), mFeatures(sdf, c.seed) {
    glm::vec3 head = c.at(Joint::Head);
    mFolds.push_back(glm::vec4(head + glm::vec3(0.0f, 0.06f, c.headRadius * 0.8f), 0.09f));  // brow and forehead
    mFolds.push_back(glm::vec4(c.at(Joint::Neck), 0.09f));
    mFolds.push_back(glm::vec4(c.at(Joint::Jaw) + glm::vec3(0.0f, 0.0f, 0.06f), 0.06f));  // around the mouth
    for (Joint j : {Joint::ForearmL, Joint::ForearmR, Joint::ShinL, Joint::ShinR, Joint::HandL, Joint::HandR,
                    Joint::UpperArmL, Joint::UpperArmR})
        mFolds.push_back(glm::vec4(c.at(j), 0.07f));
    mFolds.push_back(glm::vec4(c.at(Joint::Spine) + glm::vec3(0.0f, 0.0f, 0.15f), 0.12f));  // belly folds
}

float SkinDetail::wrinkleMask(const glm::vec3& p) const {
    float mask = 0.08f;
    for (const glm::vec4& f : mFolds) {
        glm::vec3 d = p - glm::vec3(f);
        float t = glm::dot(d, d) / (f.w * f.w);
        mask += std::exp(-t);
    }
    return std::min(mask, 1.3f);
}

SkinSample SkinDetail::sample(const glm::vec3& p) const {
    SkinSample s;
    s.feature = mFeatures.sample(p);
    const float mask = s.feature.skinMask;
    if (mask <= 0.0f) {
        s.displacement = s.feature.displacement;
        return s;
    }
    // Wrinkles run around the body (the limbs and neck hang roughly
    // vertically, and forehead lines are horizontal), so the groove noise is
    // squeezed along y: long, wavy, parallel grooves about a centimetre apart.
    glm::vec3 wp(p.x * 14.0f, p.y * 95.0f, p.z * 14.0f);
    float warp = noise::gradient(p * 9.0f, mSeed + 5u) * 2.5f;
    float groove = noise::ridged(wp + glm::vec3(0.0f, warp, 0.0f), mSeed + 11u);
    float folds = wrinkleMask(p);
    s.crease = std::min(1.0f, groove * folds) * mask;
    float wrinkles = -0.0035f * groove * folds;

    // Warts: sparse domes a few millimetres across, on 4 cm cells.
    float wart = noise::bumps(p * 25.0f, mSeed + 23u, 0.35f, 0.1f, 0.22f);
    float bigWart = noise::bumps(p * 9.0f, mSeed + 29u, 0.25f, 0.12f, 0.2f);
    s.wart = std::max(wart, bigWart) * mask;
    float warts = 0.004f * wart + 0.007f * bigWart;

    // Fine bumpy skin over everything.
    float bumps = 0.0012f * noise::fbm(p * 60.0f, mSeed + 37u, 3) + 0.002f * noise::gradient(p * 14.0f, mSeed + 41u);

    s.displacement = std::clamp((wrinkles + warts + bumps) * mask + s.feature.displacement, -kMaxAmplitude, kMaxAmplitude);
    return s;
}

} // namespace tessera::creature
