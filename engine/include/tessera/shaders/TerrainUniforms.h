// TerrainUniforms.h: what every terrain pass knows about the height field.
#ifndef TESSERA_TERRAIN_UNIFORMS_H
#define TESSERA_TERRAIN_UNIFORMS_H
#include "tessera/shaders/SharedTypes.h"

TS_NAMESPACE_BEGIN

struct TerrainUniforms {
    vec4 worldSize;   // x: extent along X (m), y: extent along Z (m), z: height scale (m at 1.0), w: sample spacing (m)
    vec4 heightTexel; // x: 1/width, y: 1/height, z: width, w: height (samples)
    vec4 tiling;      // x: patches per side, y: unused, z: patch size along X (m), w: patch size along Z (m)
};
TS_CHECK_SIZE(TerrainUniforms, 48)

TS_NAMESPACE_END

#define TS_BINDING_TERRAIN 1
#define TS_BINDING_HEIGHTMAP 2

#endif
