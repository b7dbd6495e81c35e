#include "CreatureSdf.h"

#include "SdfPrimitives.h"

#include <algorithm>
#include <cmath>

namespace tessera::creature {

namespace {

// Width of a gear band's bevelled sides (metres).
constexpr float kBandBevel = 0.003f;

} // namespace

CreatureSdf::CreatureSdf(const CreatureParams& c) {
    const float t = c.limbThickness;
    const glm::vec3 hips = c.at(Joint::Hips), spine = c.at(Joint::Spine), chest = c.at(Joint::Chest);
    const glm::vec3 head = c.at(Joint::Head);
    const float hr = c.headRadius;

    // Torso: pelvis, pot belly, a hunched back and a narrow chest.
    add(ellipsoidShape(hips + glm::vec3(0.0f, 0.04f, -0.01f), glm::vec3(0.15f, 0.11f, 0.12f), 0.0f, Joint::Hips));
    add(ellipsoidShape(spine + glm::vec3(0.0f, 0.03f, 0.11f), glm::vec3(0.93f, 0.9f, 1.0f) * c.bellyRadius, 0.06f,
                  Joint::Spine));
    add(capsuleShape(spine + glm::vec3(0.0f, 0.0f, -0.03f), chest + glm::vec3(0.0f, -0.02f, -0.05f), 0.1f, 0.12f, 0.06f,
                Joint::Spine));
    add(ellipsoidShape(chest + glm::vec3(0.0f, -0.04f, -0.01f), glm::vec3(1.0f, 0.75f, 0.75f) * c.chestRadius, 0.06f,
                  Joint::Chest));
    addTorsoGear(c);
    add(capsuleShape(chest, head + glm::vec3(0.0f, -0.03f, -0.03f), 0.065f, 0.055f, 0.05f, Joint::Neck));

    // Head: cranium, heavy brow, eyes, long nose, jaw, and the big ears.
    add(ellipsoidShape(head + glm::vec3(0.0f, 0.03f, -0.01f), glm::vec3(0.95f, 0.88f, 1.05f) * hr, 0.05f, Joint::Head));
    add(capsuleShape(head + glm::vec3(-hr * 0.55f, 0.04f, hr * 0.78f), head + glm::vec3(hr * 0.55f, 0.04f, hr * 0.78f), 0.028f,
                0.028f, 0.03f, Joint::Head));
    addEyes(c);
    glm::vec3 noseRoot = head + glm::vec3(0.0f, 0.0f, hr * 0.9f);
    glm::vec3 noseTip = noseRoot + c.noseLength * glm::normalize(glm::vec3(0.0f, -0.45f, 1.0f));
    add(capsuleShape(noseRoot, noseTip, 0.026f, 0.014f, 0.025f, Joint::Head));
    glm::vec3 jaw = c.at(Joint::Jaw), chin = c.tip(Joint::Jaw);
    add(ellipsoidShape((jaw + chin) * 0.5f, glm::vec3(1.0f, 0.55f, 0.8f) * c.jawSize, 0.04f, Joint::Jaw));
    addMouth(c);
    for (Joint ear : {Joint::EarL, Joint::EarR}) {
        glm::vec3 base = c.at(ear), tip = c.tip(ear);
        glm::vec3 dir = glm::normalize(tip - base);
        // The ear's blade faces forward and out: squash it across its length.
        glm::vec3 across = glm::normalize(glm::cross(dir, glm::vec3(0.0f, 1.0f, 0.0f)));
        SdfPrimitive p = capsuleShape(base - dir * 0.02f, tip, c.earWidth, 0.017f, 0.03f, ear);
        p.flatAxis = across;
        p.flatten = 2.0f;
        add(p);
    }

    // Long arms with simple four-fingered hands.
    for (float side : {1.0f, -1.0f}) {
        bool left = side > 0.0f;
        auto J = [&](Joint l, Joint r) { return left ? l : r; };
        glm::vec3 sh = c.at(J(Joint::ShoulderL, Joint::ShoulderR)), ua = c.at(J(Joint::UpperArmL, Joint::UpperArmR));
        glm::vec3 el = c.at(J(Joint::ForearmL, Joint::ForearmR)), wr = c.at(J(Joint::HandL, Joint::HandR));
        glm::vec3 tip = c.tip(J(Joint::HandL, Joint::HandR));
        add(capsuleShape(sh, ua, 0.06f * t, 0.055f * t, 0.05f, J(Joint::ShoulderL, Joint::ShoulderR)));
        add(capsuleShape(ua, el, 0.05f * t, 0.04f * t, 0.03f, J(Joint::UpperArmL, Joint::UpperArmR)));
        add(capsuleShape(el, wr, 0.04f * t, 0.032f * t, 0.03f, J(Joint::ForearmL, Joint::ForearmR)));
        addBracer(c, left);
        glm::vec3 dir = glm::normalize(tip - wr);
        glm::vec3 knuckle = wr + dir * 0.07f;
        SdfPrimitive palm = capsuleShape(wr, knuckle, 0.036f, 0.042f, 0.025f, J(Joint::HandL, Joint::HandR));
        palm.flatAxis = glm::vec3(1.0f, 0.0f, 0.0f);
        palm.flatten = 1.7f;
        add(palm);
        glm::vec3 fwd = glm::normalize(glm::cross(glm::vec3(side, 0.0f, 0.0f), dir)) * side;
        for (int f = 0; f < 3; ++f) {
            float spread = (static_cast<float>(f) - 1.0f) * 0.33f;
            glm::vec3 fdir = glm::normalize(dir + fwd * spread);
            glm::vec3 base = knuckle + fwd * (spread * 0.06f);
            add(capsuleShape(base, base + fdir * 0.07f, 0.015f, 0.011f, 0.012f, J(Joint::HandL, Joint::HandR)));
        }
        glm::vec3 thumbBase = wr + dir * 0.03f + glm::vec3(-side * 0.02f, 0.0f, 0.0f) + fwd * 0.02f;
        add(capsuleShape(thumbBase, thumbBase + glm::normalize(fwd * 1.0f + dir * 0.6f - glm::vec3(side * 0.4f, 0, 0)) * 0.055f,
                    0.015f, 0.011f, 0.012f, J(Joint::HandL, Joint::HandR)));
    }

    // Short bent legs and big flat feet.
    for (float side : {1.0f, -1.0f}) {
        bool left = side > 0.0f;
        auto J = [&](Joint l, Joint r) { return left ? l : r; };
        glm::vec3 th = c.at(J(Joint::ThighL, Joint::ThighR)), kn = c.at(J(Joint::ShinL, Joint::ShinR));
        glm::vec3 an = c.at(J(Joint::FootL, Joint::FootR));
        add(capsuleShape(th, kn, 0.075f * t, 0.055f * t, 0.05f, J(Joint::ThighL, Joint::ThighR)));
        add(capsuleShape(kn, an, 0.05f * t, 0.04f * t, 0.03f, J(Joint::ShinL, Joint::ShinR)));
        // The sole rests on y = 0: centre at its half-height.
        glm::vec3 centre(an.x + 0.005f * side, 0.04f, an.z + c.footLength * 0.42f);
        add(ellipsoidShape(centre, glm::vec3(0.055f, 0.04f, c.footLength * 0.6f), 0.03f, J(Joint::FootL, Joint::FootR)));
    }
    mMin -= glm::vec3(0.05f);
    mMax += glm::vec3(0.05f);
}

void CreatureSdf::add(const SdfPrimitive& primitive) {
    SdfPrimitive prim = primitive;
    if (prim.kind == SdfPrimitive::Kind::Band) {
        // Bands only thicken what is there by millimetres: the bounds'
        // margin below holds them.
        mPrims.push_back(prim);
        return;
    }
    glm::vec3 lo, hi;
    if (prim.kind == SdfPrimitive::Kind::Ellipsoid) {
        lo = prim.a - prim.radii;
        hi = prim.a + prim.radii;
        prim.boundCentre = prim.a;
        prim.boundRadius = std::max(prim.radii.x, std::max(prim.radii.y, prim.radii.z));
    } else {
        float r = std::max(prim.radii.x, prim.radii.y);
        lo = glm::min(prim.a, prim.b) - glm::vec3(r);
        hi = glm::max(prim.a, prim.b) + glm::vec3(r);
        prim.boundCentre = (prim.a + prim.b) * 0.5f;
        prim.boundRadius = glm::length(prim.b - prim.a) * 0.5f + r;
    }
    if (prim.flatten > 1.0f) prim.boundRadius = -1.0f;
    mPrims.push_back(prim);
    if (prim.subtract) return;
    mMin = glm::min(mMin, lo);
    mMax = glm::max(mMax, hi);
}

float CreatureSdf::primitiveDistance(const SdfPrimitive& prim, const glm::vec3& p) const {
    glm::vec3 q = p;
    if (prim.flatten > 1.0f) {
        // Stretch space along the axis around the primitive's start, so the
        // shape shrinks by `flatten` there. The stretched distance is too
        // long across the blade and right along it; the geometric mean keeps
        // the error moderate both ways (only the sign must be exact).
        float along = glm::dot(p - prim.a, prim.flatAxis);
        q = p + prim.flatAxis * (along * (prim.flatten - 1.0f));
    }
    float d = prim.kind == SdfPrimitive::Kind::Ellipsoid
                  ? sdf::ellipsoid(q - prim.a, prim.radii)
                  : sdf::taperedCapsule(q, prim.a, prim.b, prim.radii.x, prim.radii.y);
    if (prim.flatten > 1.0f) d /= std::sqrt(prim.flatten);
    // A clipped shape (an eyelid) is its part on the plane's positive side.
    if (prim.clip != glm::vec4(0.0f)) d = std::max(d, prim.clip.w - glm::dot(p - prim.a, glm::vec3(prim.clip)));
    return d;
}

float CreatureSdf::distanceBefore(const glm::vec3& p, size_t count, bool coarse) const {
    float d = primitiveDistance(mPrims[0], p);
    for (size_t i = 1; i < count; ++i) {
        const SdfPrimitive& prim = mPrims[i];
        if (coarse ? prim.detail : prim.coarseOnly) continue;
        if (prim.kind == SdfPrimitive::Kind::Band) {
            // The surface grown by the thickness inside the strip, ramping
            // up over kBandBevel from its sides: a square step would be
            // steeper than the sculpt can follow (its triangles fold there
            // and the baked normals turn to noise).
            const GearBand& band = mLayout.bands[prim.band];
            float ramp = std::clamp(-bandRegion(band, p) / kBandBevel, 0.0f, 1.0f);
            d -= band.thickness * ramp * ramp * (3.0f - 2.0f * ramp);
            continue;
        }
        float toBound = prim.boundRadius >= 0.0f ? glm::length(p - prim.boundCentre) - prim.boundRadius : -1e9f;
        if (prim.subtract) {
            // smoothMax(d, -x, k) is exactly d once x >= k - d.
            if (toBound > prim.blend - d + 0.01f) continue;
            d = -sdf::smoothMin(-d, primitiveDistance(prim, p), prim.blend);
            continue;
        }
        // smoothMin(d, x, k) is exactly d once x >= d + k: a shape whose
        // bounding sphere is that far away cannot change the result (the
        // extra centimetre covers the ellipsoid estimate's slack).
        if (toBound > d + prim.blend + 0.01f) continue;
        d = sdf::smoothMin(d, primitiveDistance(prim, p), prim.blend);
    }
    // Cut by the ground plane: flat soles exactly at y = 0, whatever the
    // smooth unions above them did.
    return std::max(d, -p.y);
}

glm::vec3 CreatureSdf::gradient(const glm::vec3& p, float h, float* value) const {
    const glm::vec3 k0(1, -1, -1), k1(-1, -1, 1), k2(-1, 1, -1), k3(1, 1, 1);
    float f0 = distance(p + k0 * h), f1 = distance(p + k1 * h), f2 = distance(p + k2 * h), f3 = distance(p + k3 * h);
    if (value) *value = 0.25f * (f0 + f1 + f2 + f3);
    return (k0 * f0 + k1 * f1 + k2 * f2 + k3 * f3) / (4.0f * h);
}

glm::vec3 CreatureSdf::project(const glm::vec3& p, int steps, float maxStep, glm::vec3* normal) const {
    glm::vec3 q = p;
    glm::vec3 g(0.0f, 1.0f, 0.0f);
    for (int i = 0; i < steps; ++i) {
        float d = 0.0f;
        g = gradient(q, 1e-3f, &d);
        float g2 = glm::dot(g, g);
        if (g2 < 1e-12f) break;
        q -= g * (d / g2);
        glm::vec3 moved = q - p;
        float len = glm::length(moved);
        if (len > maxStep) q = p + moved * (maxStep / len);
    }
    if (normal) {
        g = gradient(q);
        float len = glm::length(g);
        *normal = len > 1e-9f ? g / len : glm::vec3(0.0f, 1.0f, 0.0f);
    }
    return q;
}

void CreatureSdf::boneDistances(const glm::vec3& p, float* out) const {
    std::fill(out, out + kJointCount, 1e9f);
    for (const SdfPrimitive& prim : mPrims) {
        // Skinning follows the cage's field: detail belongs to the shapes
        // it sits on (so the cage's weights are as they were before it).
        if (prim.detail) continue;
        float& slot = out[static_cast<uint32_t>(prim.bone)];
        slot = std::min(slot, primitiveDistance(prim, p));
    }
}

} // namespace tessera::creature
