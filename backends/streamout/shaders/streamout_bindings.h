// streamout_bindings.h: binding numbers of streamout's own passes, shared by
// the C++ side and the shaders. They follow the terrain's (0..7) and the
// emulated tessellator's (8, 9) so one pass can use all of them.
#ifndef TESSERA_STREAMOUT_BINDINGS_H
#define TESSERA_STREAMOUT_BINDINGS_H

/// The transformed cage: RGBA32F texel buffer, one texel per control-mesh
/// grid vertex (world xyz, grid vertex ID), read with texelFetch (D3D10's
/// Buffer<float4>.Load).
#define SO_BINDING_CAGE 10

#endif
