#include "tessera/character/ImpostorAtlas.h"

namespace tessera::character {

uint64_t ImpostorAtlas::bytes() const {
    uint64_t total = 0;
    for (const std::vector<uint8_t>& level : albedo) total += level.size();
    for (const std::vector<uint8_t>& level : normal) total += level.size();
    return total;
}

} // namespace tessera::character
