// BakedAnimationTestLayout.h: the buffers of the baked animation GPU test
// (tests/gpu/baked_animation_test.cpp and shaders/baked_animation.comp),
// written once for both languages.
#ifndef TESSERA_BAKED_ANIMATION_TEST_LAYOUT_H
#define TESSERA_BAKED_ANIMATION_TEST_LAYOUT_H
#include "tessera/shaders/SharedTypes.h"

TS_NAMESPACE_BEGIN

/// One evaluation: x = global clip, y = joint; phase in phase.x.
struct TsBakedTestQuery {
    uvec4 clipJoint;
    vec4 phase;
};
TS_CHECK_SIZE(TsBakedTestQuery, 32)

/// Push constants: x = query count.
struct TsBakedTestParams {
    uvec4 count;
};
TS_CHECK_SIZE(TsBakedTestParams, 16)

TS_NAMESPACE_END

#endif
