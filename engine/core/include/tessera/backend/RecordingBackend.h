#pragma once
/// @file RecordingBackend.h
/// A decorator that logs every contract command by name before forwarding it,
/// generated from BackendApi.inc (Filament's command recorder). Tests use it
/// to check the host's frame logic drives a backend in the documented order.

#include "tessera/backend/Backend.h"

#include <memory>
#include <string>
#include <vector>

namespace tessera::backend {

class RecordingBackend final : public Backend {
public:
    explicit RecordingBackend(Backend& inner) : mInner(inner) {}

    /// Command names in call order, e.g. {"initialize", "beginFrame", ...}.
    const std::vector<std::string>& commands() const { return mCommands; }
    void clear() { mCommands.clear(); }

#define TESSERA_BACKEND_COMMAND(ReturnType, name, params, args) \
    ReturnType name params override {                           \
        mCommands.emplace_back(#name);                          \
        return mInner.name args;                                \
    }
#include "tessera/backend/BackendApi.inc"

private:
    Backend& mInner;
    std::vector<std::string> mCommands;
};

} // namespace tessera::backend
