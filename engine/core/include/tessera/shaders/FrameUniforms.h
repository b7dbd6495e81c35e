// FrameUniforms.h: per-frame constants every pass reads (set 0, binding 0).
#ifndef TESSERA_FRAME_UNIFORMS_H
#define TESSERA_FRAME_UNIFORMS_H
#include "tessera/shaders/SharedTypes.h"

TS_NAMESPACE_BEGIN

struct FrameUniforms {
    mat4 viewProjection;
    mat4 view;
    vec4 cameraPosition; // xyz: world position, w: time in seconds
    vec4 sunDirection;   // xyz: unit vector towards the sun, w: unused
    vec4 fogColor;       // rgb: plain look's fog colour (the clear colour), a: its fog density per metre
    vec4 viewport;       // x: width, y: height, z: 1/width, w: 1/height (pixels)
    vec4 look;           // x: TS_LOOK_*, y: exposure, z: fog height falloff (1/m), w: fog density at the camera (1/m)
    vec4 sunColor;       // rgb: sun radiance above the atmosphere (linear), a: cosine of the sun disc's radius
    vec4 characterShadow; // the characters' shadow mask: xy: world XZ of its min corner, z: 1/side (1/m), w: 1 when drawn this frame
    vec4 terrainResolve;  // x: 1 when the terrain's full-look shading is deferred to the resolve pass
                          //    (its main-pass fragments store their distance), y: metres a pixel spans per
                          //    metre of distance (2 / (height * |projection[1][1]|)), zw: 1 / projection[0][0],
                          //    1 / projection[1][1] (a view ray's slopes per unit of NDC)
};
TS_CHECK_SIZE(FrameUniforms, 256)

TS_NAMESPACE_END

#define TS_BINDING_FRAME 0

// FrameUniforms::look.x, the same numbers as backend::Look.
#define TS_LOOK_PLAIN 0u
#define TS_LOOK_FULL 1u

#endif
