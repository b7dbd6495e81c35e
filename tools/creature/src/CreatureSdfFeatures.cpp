// CreatureSdf's close-up features: eyes under lids, the mouth with teeth
// and tusks, and the leather gear. Split from CreatureSdf.cpp, which builds
// the body; each function here adds its shapes at its place in the union
// (the order matters: a carve or a band acts on what came before it).

#include "CreatureSdf.h"

#include "SdfNoise.h"

#include <algorithm>
#include <cmath>

namespace tessera::creature {

float CreatureSdf::rayHit(const glm::vec3& origin, const glm::vec3& dir, float maxT) const {
    float t = 0.0f;
    for (int i = 0; i < 400 && t < maxT; ++i) {
        float d = distance(origin + dir * t);
        if (d < 2e-4f) return t;
        // The smooth unions and squashes overestimate a little: step short.
        t += std::max(d * 0.8f, 2e-4f);
    }
    return maxT;
}

void CreatureSdf::addEyes(const CreatureParams& c) {
    const glm::vec3 head = c.at(Joint::Head);
    const float hr = c.headRadius, r = c.eyeRadius;
    // Right eye first: the order of the smooth unions is the order the
    // cage's field always had, which keeps the cage byte-identical.
    for (int i : {1, 0}) {
        const float side = i == 0 ? 1.0f : -1.0f;  // eyes[0] is the left (+X) eye
        // The cage keeps the soft mound the eyes were before the sockets
        // and lids: a protruding ball with a crisp crease pinches the
        // simplified cage and its far mesh (open edges, kinked normals).
        SdfPrimitive mound = ellipsoidShape(head + glm::vec3(side * hr * 0.33f, 0.005f, hr * 0.86f), glm::vec3(0.022f),
                                            0.012f, Joint::Head);
        mound.coarseOnly = true;
        add(mound);
        EyeLayout& eye = mLayout.eyes[i];
        eye.radius = r;
        // Bulging goblin eyes: the centre sits 0.3 radii under the brow's
        // surface, so most of the ball stands proud for the lids to hug.
        glm::vec3 onFace(side * hr * 0.34f, head.y + 0.004f, head.z + 0.5f);
        float z = onFace.z - rayHit(onFace, glm::vec3(0.0f, 0.0f, -1.0f), 0.5f);
        eye.centre = glm::vec3(onFace.x, onFace.y, z - 0.3f * r);
        eye.gaze = glm::normalize(glm::vec3(side * 0.1f, -0.12f, 1.0f));
        // The socket: a smooth pit a little wider than the ball, so the
        // corners of the eye read as recesses at close range. The blends
        // here are as soft as still reads crisp: the displacement map has
        // ~1.5 mm texels, and sharper creases where a UV seam crosses the
        // eye leave the two charts' bilinear fetches disagreeing by more
        // than the seam test's 0.1 mm (LoadedCreatureSeams).
        SdfPrimitive socket = ellipsoidShape(eye.centre, glm::vec3(r * 1.25f), 0.016f, Joint::Head);
        socket.subtract = true;
        socket.detail = true;
        add(socket);
        SdfPrimitive ball = ellipsoidShape(eye.centre, glm::vec3(r), 0.006f, Joint::Head);
        ball.detail = true;
        add(ball);
        // Lids: shells around the ball cut by a plane each. The upper lid's
        // edge drops towards the nose (a scowl) and sits lidDroop radii
        // above the centre; the lower one covers the bottom of the ball.
        SdfPrimitive upper = ellipsoidShape(eye.centre, glm::vec3(r * 1.14f), 0.005f, Joint::Head);
        upper.clip = glm::vec4(glm::normalize(glm::vec3(-side * 0.35f, 1.0f, 0.0f)), c.lidDroop * r);
        upper.detail = true;
        add(upper);
        SdfPrimitive lower = ellipsoidShape(eye.centre, glm::vec3(r * 1.08f), 0.005f, Joint::Head);
        lower.clip = glm::vec4(0.0f, -1.0f, 0.0f, 0.55f * r);
        lower.detail = true;
        add(lower);
    }
}

void CreatureSdf::addMouth(const CreatureParams& c) {
    const glm::vec3 jawCentre = (c.at(Joint::Jaw) + c.tip(Joint::Jaw)) * 0.5f;
    const float w = c.mouthWidth;
    // The lip line runs across the upper front of the jaw, under the nose;
    // its corners turn up by the grin.
    const float y = jawCentre.y + 0.15f * 0.55f * c.jawSize;
    const float lift = 0.012f * c.grin;
    // Start the rays just in front of the jaw so a long nose hanging over
    // the mouth does not catch them.
    const float zStart = jawCentre.z + 0.8f * c.jawSize + 0.03f;
    auto onFace = [&](float x, float yy) {
        glm::vec3 o(x, yy, zStart);
        if (distance(o) <= 0.0f) o.z += 0.05f;
        return o - glm::vec3(0.0f, 0.0f, rayHit(o, glm::vec3(0.0f, 0.0f, -1.0f), 0.3f));
    };
    const glm::vec3 mid = onFace(0.0f, y);
    for (int i = 0; i < 2; ++i) {
        const float side = i == 0 ? 1.0f : -1.0f;
        glm::vec3 corner = onFace(side * w, y + lift);
        // The slit's axis lies just under the skin: a groove about 5 mm deep.
        CapsuleLayout& slit = mLayout.mouthSlit[i];
        slit = {mid - glm::vec3(0.0f, 0.0f, 0.001f), corner - glm::vec3(0.0f, 0.0f, 0.002f), 0.0045f, 0.0025f};
        SdfPrimitive carve = capsuleShape(slit.a, slit.b, slit.ra, slit.rb, 0.003f, Joint::Jaw);
        carve.subtract = true;
        carve.detail = true;
        add(carve);
    }
    // A point on the lip line's axis at x.
    auto lipAxis = [&](float x) {
        const CapsuleLayout& s = mLayout.mouthSlit[x >= 0.0f ? 0 : 1];
        float f = std::min(std::abs(x) / w, 1.0f);
        return s.a + (s.b - s.a) * f;
    };
    // Upper teeth: short pointed pegs hanging into the groove, a little
    // uneven (sizes from the seed).
    const uint32_t n = std::max(1u, c.toothCount);
    for (uint32_t t = 0; t < n; ++t) {
        float x = ((static_cast<float>(t) + 0.5f) / static_cast<float>(n) * 2.0f - 1.0f) * 0.62f * w;
        float size = 0.85f + 0.35f * noise::hashToUnit(noise::hashLattice(static_cast<int32_t>(t), 3, 5, c.seed));
        glm::vec3 axis = lipAxis(x);
        CapsuleLayout tooth{axis + glm::vec3(0.0f, 0.004f, -0.002f),
                            axis + glm::vec3(0.0f, -0.0045f * size, 0.0015f), 0.0028f * size, 0.0007f};
        mLayout.teeth.push_back(tooth);
        SdfPrimitive shape = capsuleShape(tooth.a, tooth.b, tooth.ra, tooth.rb, 0.001f, Joint::Head);
        shape.detail = true;
        add(shape);
    }
    // Lower tusks near the corners, up and out over the upper lip.
    for (int i = 0; i < 2; ++i) {
        const float side = i == 0 ? 1.0f : -1.0f;
        glm::vec3 base = lipAxis(side * 0.8f * w) + glm::vec3(0.0f, -0.005f, -0.001f);
        glm::vec3 dir = glm::normalize(glm::vec3(side * 0.2f, 1.0f, 0.35f));
        CapsuleLayout& tusk = mLayout.tusks[i];
        tusk = {base, base + dir * c.tuskLength, 0.0055f, 0.0012f};
        SdfPrimitive shape = capsuleShape(tusk.a, tusk.b, tusk.ra, tusk.rb, 0.002f, Joint::Jaw);
        shape.detail = true;
        add(shape);
    }
}

void CreatureSdf::addBand(const GearBand& band) {
    GearBand b = band;
    b.primitive = static_cast<uint32_t>(mPrims.size());
    SdfPrimitive op;
    op.kind = SdfPrimitive::Kind::Band;
    op.band = static_cast<uint32_t>(mLayout.bands.size());
    op.detail = true;
    mLayout.bands.push_back(b);
    add(op);
}

void CreatureSdf::addTorsoGear(const CreatureParams& c) {
    const glm::vec3 hips = c.at(Joint::Hips), spine = c.at(Joint::Spine), chest = c.at(Joint::Chest);
    // The belt: across the lower slope of the pot belly, tipped down a
    // little at the front, where the buckle shows from the front and from
    // above (lower down, the belly hides it). Its bound is narrower than
    // the hanging arms are far apart.
    GearBand belt;
    belt.kind = GearBand::Kind::Belt;
    belt.centre = hips + glm::vec3(0.0f, 0.08f, 0.0f);
    belt.axis = glm::normalize(glm::vec3(0.0f, 1.0f, 0.08f));
    belt.halfWidth = 0.021f;
    belt.thickness = 0.007f;
    belt.bound = {belt.centre + glm::vec3(0.0f, 0.0f, -0.3f), belt.centre + glm::vec3(0.0f, 0.0f, 0.4f), 0.235f, 0.235f};
    addBand(belt);
    // The buckle: where the belt's mid-plane leaves the front of the body.
    glm::vec3 forward = glm::normalize(glm::cross(glm::vec3(1.0f, 0.0f, 0.0f), belt.axis));
    glm::vec3 origin = belt.centre + forward * 0.5f;
    mLayout.buckleCentre = origin - forward * rayHit(origin, -forward, 0.5f);
    mLayout.buckleNormal = forward;

    if (!c.chestStrap) return;
    // A bandolier from the left shoulder to the right hip: the plane holds
    // the torso's forward direction and a line leaning left from the spine.
    glm::vec3 up = glm::normalize(chest - spine);
    glm::vec3 torsoForward = glm::normalize(glm::cross(glm::vec3(1.0f, 0.0f, 0.0f), up));
    glm::vec3 along = glm::normalize(glm::vec3(0.6f, 0.0f, 0.0f) + up);
    GearBand strap;
    strap.kind = GearBand::Kind::Strap;
    strap.centre = (spine + chest) * 0.5f;
    strap.axis = glm::normalize(glm::cross(along, torsoForward));
    strap.halfWidth = 0.017f;
    strap.thickness = 0.005f;
    // The bound's lower cap ends at the belt on the right hip, so the strap
    // runs into the belt instead of wrapping under the pelvis.
    strap.bound = {hips + glm::vec3(0.0f, 0.3f, 0.1f), chest + glm::vec3(0.0f, 0.1f, 0.0f), 0.3f, 0.3f};
    addBand(strap);
}

void CreatureSdf::addBracer(const CreatureParams& c, bool left) {
    if (!c.bracers) return;
    const glm::vec3 el = c.at(left ? Joint::ForearmL : Joint::ForearmR), wr = c.at(left ? Joint::HandL : Joint::HandR);
    const float len = glm::length(wr - el);
    GearBand bracer;
    bracer.kind = GearBand::Kind::Bracer;
    bracer.axis = (wr - el) / len;
    // The lower half of the forearm, stopping short of the wrist's bend.
    bracer.centre = el + (wr - el) * 0.66f;
    bracer.halfWidth = 0.22f * len;
    bracer.thickness = 0.006f;
    const float reach = 0.065f * c.limbThickness;
    bracer.bound = {el, wr, reach, reach};
    addBand(bracer);
}

} // namespace tessera::creature
