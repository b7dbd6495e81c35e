#pragma once
/// @file SelectedBackend.h
/// Choosing a backend: loading its plugin, creating the Vulkan instance and
/// device it needs, and checking it can run there; private to the runtime
/// (a host only names the backend, Options::backend).

#include "tessera/runtime/Options.h"
#include "tessera/backend/BackendRegistry.h"
#include "tessera/backend/PluginLoader.h"
#include "tessera/gpu/Device.h"
#include "tessera/gpu/Instance.h"

#include <memory>
#include <string>

namespace tessera::runtime {

/// The chosen backend with the instance and device it runs on (null for the
/// null backend). Members are declared so that the backend is destroyed
/// first and the instance last.
struct SelectedBackend {
    std::unique_ptr<gpu::Instance> instance;
    std::unique_ptr<gpu::Device> device;
    backend::BackendRegistry registry;
    backend::BackendPtr backend;
    backend::BackendCapabilities capabilities;
};

/// Chooses and creates the backend (and device) described by `options`:
/// Options::backend, else the first the device runs of kBackendPreference
/// (kCpuBackendPreference on a CPU rasterizer).
Result<std::unique_ptr<SelectedBackend>> selectBackend(const Options& options);

/// Replaces `selected`'s backend with a new instance of backend `name` on the
/// device `selected` already holds (loading its plugin from the options'
/// search path when it is not loaded yet): what switching backends at run
/// time needs. The old backend is left untouched when this fails, which it
/// does with a message naming the backend when the plugin is missing, when
/// the backend cannot run on the device, or when it needs a device and the
/// session has none (the null backend's sessions) or the other way round.
/// The new backend is not initialised yet.
Result<backend::BackendPtr> createBackendOnDevice(SelectedBackend& selected, const Options& options,
                                                  const std::string& name, backend::BackendCapabilities& caps);

/// The plugin loader searching the options' plugin directories.
backend::PluginLoader pluginLoaderFor(const Options& options);
/// The Vulkan instance the options ask for (validation, windowing).
Result<std::unique_ptr<gpu::Instance>> makeInstance(const Options& options);
/// What `caps` says the device lacks, comma-separated.
std::string joinMissing(const backend::BackendCapabilities& caps);

} // namespace tessera::runtime
