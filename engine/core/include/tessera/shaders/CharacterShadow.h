// CharacterShadow.h: the characters' shadows on the terrain, a mask in
// terrain space rendered from one elongated ellipse per character (feet,
// height) cast along the sun (backends/common CharacterShadowPass), which
// the terrain's shading multiplies into its sunlight.
#ifndef TESSERA_CHARACTER_SHADOW_H
#define TESSERA_CHARACTER_SHADOW_H
#include "tessera/shaders/SharedTypes.h"

TS_NAMESPACE_BEGIN

struct CharacterShadowParams {
    vec4 region; // xy: world XZ of the mask's min corner (metres), z: its side (metres), w: 1 / side
    vec4 sun;    // xyz: unit vector towards the sun, w: largest shadow length in character heights
};
TS_CHECK_SIZE(CharacterShadowParams, 32)

TS_NAMESPACE_END

// Texels on a side of the mask (R8: darkness).
#define TS_CHARACTER_SHADOW_SIZE 1024u
// Darkness at the centre of a character's shadow (sunlight kept: 1 - this).
#define TS_CHARACTER_SHADOW_STRENGTH 0.75

#endif
