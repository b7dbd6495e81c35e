#pragma once
/// @file TechniqueExtension.h
/// A backend's own per-object resources: what its technique keeps for one
/// character, crowd or subdivision surface beside the shared GPU object
/// (r2vb's render targets, streamout's query pools and stream buffers, ...).
/// The backend makes one in its attach hook when the object is created
/// (BasicCharacterBackend::attachCharacterResources, attachCrowdResources,
/// BasicSubdivBackend::attachSubdivResources) and hands it to the object,
/// which owns it: it is released with the object, after the frames that
/// used it have retired, and its bytes are counted with the object's.

#include <cstdint>
#include <memory>
#include <utility>

namespace tessera::backends {

class TechniqueExtension {
public:
    virtual ~TechniqueExtension() = default;
    /// Device bytes of the extension's buffers and targets (FrameReport
    /// counts them beside the object's own each frame it is drawn).
    virtual uint64_t bytes() const { return 0; }
};

/// The slot GpuCharacter, GpuCrowd and GpuSubdiv keep their extension in.
class ExtensionSlot {
public:
    /// The backend's extension (null until it attaches one).
    TechniqueExtension* extension() const { return mExtension.get(); }
    /// The extension as the backend's own type (which attached it).
    template <class T>
    T& extensionAs() const {
        return *static_cast<T*>(mExtension.get());
    }
    void attach(std::unique_ptr<TechniqueExtension> extension) { mExtension = std::move(extension); }
    /// Bytes of the extension (0 without one).
    uint64_t extensionBytes() const { return mExtension ? mExtension->bytes() : 0; }

private:
    std::unique_ptr<TechniqueExtension> mExtension;
};

} // namespace tessera::backends
