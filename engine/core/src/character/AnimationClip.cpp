#include "tessera/character/AnimationClip.h"

#include <algorithm>

namespace tessera::character {

float AnimationClip::duration() const {
    float end = 0.0f;
    for (const AnimationChannel& channel : channels) {
        if (!channel.times.empty()) end = std::max(end, channel.times.back());
    }
    return end;
}

} // namespace tessera::character
