// mesh_capture_triangle.glsl: the capture test's triangle task-to-mesh
// hand-over, the character's (meshshader_character.glsl) under the test's
// names: workgroup g draws piece g % pieces of patch firstTriangle + g / pieces.
#ifndef MESH_CAPTURE_TRIANGLE_GLSL
#define MESH_CAPTURE_TRIANGLE_GLSL
#include "../support/MeshCaptureTestLayout.h"

struct CaptureTrianglePayload {
    uint firstTriangle;
    uint pieces;
};

#endif
