#pragma once
/// @file PluginApi.h
/// What a backend plugin exports. Every plugin is a shared module in its own
/// folder under backends/ (or plugins/) with exactly one C entry point:
///
/// @code
///   TESSERA_REGISTER_PLUGIN(registry) {
///       registry.registerBackend({"mybackend", &createMyBackend, &destroyMyBackend});
///   }
/// @endcode
///
/// The entry point's symbol carries the ABI version (`registerPlugin_v8`), so a
/// host never calls into a plugin built against a different contract: the
/// loader finds `registerPlugin_v<N>` with the wrong N and reports the mismatch
/// instead. Bump kPluginAbiVersion whenever BackendApi.inc or any type that
/// crosses the boundary changes layout or namespace (7: DeviceFeatures and
/// FeatureMask moved to tessera::device, SubdivMeshData to the contract; 8:
/// DeviceFeatures' mesh-shader fields, BackendCapabilities::usesMeshShaders; 9:
/// FrameInfo::shadows and shadowCascades, BackendCapabilities::cascadedShadows;
/// 10: CrowdCharacterDesc::farCasterIndices, Shadows::None; 11:
/// CrowdDrawInfo::occluders, CrowdLodParams::occluder; 12: the impostor
/// tier: TS_LOD_TIERS 4 (CrowdTierCounts, CrowdTiers, FrameReport's crowd
/// counts), 3-bit state tiers, CrowdCharacterDesc::impostor).

#include "tessera/backend/Backend.h"

#include <cstdint>

namespace tessera::backend {

/// The contract version this host and its plugins are built against.
inline constexpr uint32_t kPluginAbiVersion = 12;

#define TESSERA_PLUGIN_STRINGIFY_(x) #x
#define TESSERA_PLUGIN_STRINGIFY(x) TESSERA_PLUGIN_STRINGIFY_(x)
#define TESSERA_PLUGIN_CONCAT_(a, b) a##b
#define TESSERA_PLUGIN_CONCAT(a, b) TESSERA_PLUGIN_CONCAT_(a, b)
/// Must equal kPluginAbiVersion (a macro because it builds a symbol name).
#define TESSERA_PLUGIN_ABI_VERSION 12
#define TESSERA_PLUGIN_ENTRY_SYMBOL TESSERA_PLUGIN_CONCAT(registerPlugin_v, TESSERA_PLUGIN_ABI_VERSION)
/// The prefix shared by every version of the entry point, for mismatch reports.
#define TESSERA_PLUGIN_ENTRY_PREFIX "registerPlugin_v"

static_assert(TESSERA_PLUGIN_ABI_VERSION == kPluginAbiVersion);

/// One backend a plugin offers. Backend objects are created and destroyed by
/// the plugin's own code, so allocator and runtime never mix across modules.
struct BackendPluginDesc {
    const char* name = nullptr;
    Backend* (*create)() = nullptr;
    void (*destroy)(Backend*) = nullptr;
};

/// The host-side registry a plugin's entry point fills in.
class PluginRegistry {
public:
    virtual ~PluginRegistry() = default;
    /// Registers a backend. The host rejects a name already registered.
    virtual void registerBackend(const BackendPluginDesc& desc) = 0;
};

} // namespace tessera::backend

/// Defines the plugin's entry point; the body receives `registryName`.
#define TESSERA_REGISTER_PLUGIN(registryName)                                                      \
    extern "C" __attribute__((visibility("default"))) void TESSERA_PLUGIN_ENTRY_SYMBOL(            \
        ::tessera::backend::PluginRegistry& registryName)

/// The type of the entry point, as the loader sees it.
using TesseraPluginEntry = void (*)(::tessera::backend::PluginRegistry&);
