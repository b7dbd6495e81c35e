#pragma once
/// @file BackendSelection.h
/// Loads backend plugins, creates the Vulkan instance and device a backend
/// needs, and answers --list-backends / --list-devices.

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

/// Backends in order of preference when --backend is not given; the first
/// the device can run is used (bgfx's scored fallback).
inline constexpr const char* kBackendPreference[] = {"hulldomain", "streamout", "r2vb"};

/// Chooses and creates the backend (and device) described by `options`.
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
/// Prints every backend with its capabilities, checked against the device.
Status listBackends(const Options& options);
/// Prints the Vulkan devices.
Status listDevices(const Options& options);

/// Messages the Khronos validation layer reported so far in this process
/// (Options::validation turns it on); a host fails its run on any.
uint64_t validationMessages();

} // namespace tessera::runtime
