// A GPU backend that breaks a Vulkan valid-usage rule on purpose (a viewport
// count of zero, harmless to any driver), so the tests can prove that the
// validation layer is really on and that any message fails the run.
#include "StubBackend.h"

#include "tessera/gpu/FrameContext.h"
#include "tessera/gpu/RenderTarget.h"

namespace {

using namespace tessera;

class InvalidUsageBackend final : public test::StubBackend {
public:
    InvalidUsageBackend() : StubBackend("invalid-usage", "test backend that violates a Vulkan valid-usage rule") {}
    void endFrame() override {
        const float clear[4] = {0, 0, 0, 1};
        frame()->target().beginRendering(frame()->cmd(), clear);
        VkViewport viewport{};
        vkCmdSetViewport(frame()->cmd(), 0, 0, &viewport); // VUID-vkCmdSetViewport-viewportCount-arraylength
        frame()->target().endRendering(frame()->cmd());
    }
};

backend::Backend* create() { return new InvalidUsageBackend(); }
void destroy(backend::Backend* b) { delete b; }

} // namespace

TESSERA_REGISTER_PLUGIN(registry) { registry.registerBackend({"invalid-usage", &create, &destroy}); }
