#pragma once
/// @file BackendSelection.h
/// What a host asks about backends and devices before or after a run:
/// --list-backends and --list-devices, the order backends are tried in, and
/// the validation layer's count. Choosing the backend and making its device
/// is the render session's own business (RenderSession::create).

#include "tessera/runtime/Options.h"

#include <cstdint>

namespace tessera::runtime {

/// Backends in order of preference on a GPU when Options::backend is
/// empty; the first the device can run is used (bgfx's scored fallback).
/// hulldomain first: hardware tessellation to level 64 and compute, the
/// fastest on the GPUs measured. meshshader comes last: on lavapipe it is the
/// slowest of the four at equal triangles (docs/BACKENDS.md, "meshshader"),
/// so it runs when named, or on a device that runs none of the others.
inline constexpr const char* kBackendPreference[] = {"hulldomain", "streamout", "r2vb", "meshshader"};

/// The same on a CPU rasterizer (lavapipe, the default device): streamout
/// first. There the emulated tessellator's vertex-shader passes cost far less
/// than the tessellation stages (the terrain flythrough at --tess-target 8:
/// 49 against 73 ms a frame on two cores; the default showcase 68 to 71
/// against 78 to 84; docs/BACKENDS.md, "The default backend").
inline constexpr const char* kCpuBackendPreference[] = {"streamout", "hulldomain", "r2vb", "meshshader"};

/// The GPU backends by pipeline generation, oldest first (D3D9 to D3D12):
/// the window's keys 1 to 4.
inline constexpr const char* kBackendGenerations[] = {"r2vb", "streamout", "hulldomain", "meshshader"};

/// Prints every backend with its capabilities, checked against the device.
Status listBackends(const Options& options);
/// Prints the Vulkan devices.
Status listDevices(const Options& options);

/// Messages the Khronos validation layer reported so far in this process
/// (Options::validation turns it on); a host fails its run on any.
uint64_t validationMessages();

} // namespace tessera::runtime
