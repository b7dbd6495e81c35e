#pragma once
// StubBackend: the template backend (plugins/BackendTemplate), drawing
// nothing, made a GPU backend under another name, for the test plugins that
// each break one rule (a valid-usage violation, a failing initialize). They
// override only what they break.
#include "TemplateBackend.h"

#include <string>

namespace tessera::test {

class StubBackend : public plugins::TemplateBackend {
public:
    StubBackend(std::string name, std::string description)
        : mName(std::move(name)), mDescription(std::move(description)) {}

    backend::BackendCapabilities capabilities(const device::DeviceFeatures* device) override {
        backend::BackendCapabilities caps = TemplateBackend::capabilities(device);
        caps.name = mName;
        caps.description = mDescription;
        caps.requiresGpu = true;
        return caps;
    }
    void beginFrame(const backend::FrameInfo& frame) override {
        TemplateBackend::beginFrame(frame);
        mFrame = frame.gpu;
    }

protected:
    gpu::FrameContext* frame() const { return mFrame; }

private:
    std::string mName, mDescription;
    gpu::FrameContext* mFrame = nullptr;
};

} // namespace tessera::test
