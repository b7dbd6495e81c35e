#pragma once
/// @file Handles.h
/// Typed handles for resources that cross the backend boundary.
///
/// As in Filament (`Handle<HwTexture>`), a resource created by a backend is
/// named by a small typed integer; the tag type makes a TerrainHandle and a
/// CharacterHandle impossible to mix up.

#include <cstdint>

namespace tessera::backend {

template <class Tag>
struct Handle {
    static constexpr uint32_t kInvalid = UINT32_MAX;
    uint32_t id = kInvalid;

    bool valid() const { return id != kInvalid; }
    bool operator==(const Handle&) const = default;
};

struct TerrainTag;
/// A terrain uploaded with Backend::createTerrain.
using TerrainHandle = Handle<TerrainTag>;

struct CharacterTag;
/// A character uploaded with Backend::createCharacter.
using CharacterHandle = Handle<CharacterTag>;

} // namespace tessera::backend
