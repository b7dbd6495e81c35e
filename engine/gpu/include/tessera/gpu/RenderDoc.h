#pragma once
/// @file RenderDoc.h
/// A frame capture through RenderDoc's in-application API, for `--renderdoc
/// N` (docs/BACKENDS.md, "Captures"): the capture holds every pass's debug
/// label and every object's name, as the profiler's traces do.
///
/// RenderDoc captures Vulkan through its implicit layer, which the loader
/// only enables when ENABLE_VULKAN_RENDERDOC_CAPTURE=1 is set before the
/// instance is created; so load() must run first. When librenderdoc.so is
/// missing (Debian's `renderdoc` package not installed) load() says so and
/// nothing else changes.

#include "tessera/core/Result.h"

#include <filesystem>
#include <memory>
#include <string>

namespace tessera::gpu {

class Instance;

class RenderDoc {
public:
    /// Loads librenderdoc.so (or the file `TESSERA_RENDERDOC_LIBRARY`
    /// names) and turns its layer on for the instance made next. Captures go
    /// to files named from `pathTemplate` (RenderDoc 1.24 writes `<template>_capture.rdc`; end() returns the name). The error
    /// says why RenderDoc cannot be used and how to get it.
    static Result<std::unique_ptr<RenderDoc>> load(const std::filesystem::path& pathTemplate);
    ~RenderDoc();
    RenderDoc(const RenderDoc&) = delete;
    RenderDoc& operator=(const RenderDoc&) = delete;

    /// Turns RenderDoc's layer off again for instances created from now on
    /// (the library stays loaded; begin() and end() must not be called).
    void disableLayer();
    /// The in-application API version the library serves, "1.6.0".
    std::string version() const;
    /// Starts capturing everything `instance`'s device records and submits.
    void begin(const Instance& instance);
    /// Ends the capture and returns the file RenderDoc wrote; an error if it
    /// wrote none (e.g. the layer was not active on `instance`).
    Result<std::filesystem::path> end(const Instance& instance);

private:
    RenderDoc() = default;
    void* mLibrary = nullptr;
    const void* mApi = nullptr; ///< RENDERDOC_API_1_1_2, kept out of this header
};

} // namespace tessera::gpu
