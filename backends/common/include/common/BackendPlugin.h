#pragma once
/// @file BackendPlugin.h
/// A backend plugin's registration, written once: the create and destroy
/// functions the host calls (in the plugin's own module, so allocator and
/// runtime never mix) for a backend class. A backend's file ends with
///   TESSERA_REGISTER_PLUGIN(registry) {
///       registry.registerBackend(tessera::backends::backendPlugin<MyBackend>("mybackend"));
///   }

#include "tessera/backend/PluginApi.h"

namespace tessera::backends {

/// The plugin description of `BackendT` under `name`.
template <class BackendT>
backend::BackendPluginDesc backendPlugin(const char* name) {
    return {name, []() -> backend::Backend* { return new BackendT(); }, [](backend::Backend* b) { delete b; }};
}

} // namespace tessera::backends
