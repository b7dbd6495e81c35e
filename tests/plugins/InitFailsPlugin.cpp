// A GPU backend whose initialize fails halfway, as a real one does when a
// pipeline will not build on the device: it has already made a buffer, an
// image, a sampler and a descriptor-set layout. The host must call shutdown (the contract: it releases
// whatever initialize made), report the backend and the reason, and leave
// the validation layer's object tracking nothing to find; a switch to it must
// leave the old backend drawing (tests/runtime/backend_init_failure_test.cpp).
#include "StubBackend.h"

#include "tessera/gpu/Buffer.h"
#include "tessera/gpu/Device.h"
#include "tessera/gpu/Image.h"
#include "tessera/gpu/Sampler.h"

#include <optional>

namespace {

using namespace tessera;

class InitFailsBackend final : public test::StubBackend {
public:
    InitFailsBackend() : StubBackend("init-fails", "test backend whose initialize fails after making GPU objects") {}
    Status initialize(const backend::BackendInitInfo& info) override {
        gpu::Device& device = *info.device;
        mBuffer.emplace(device, 1u << 16, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, gpu::MemoryUsage::GpuOnly,
                        "init-fails.buffer");
        gpu::ImageDesc image;
        image.width = image.height = 64;
        image.format = VK_FORMAT_R8G8B8A8_UNORM;
        image.usage = VK_IMAGE_USAGE_SAMPLED_BIT;
        image.name = "init-fails.image";
        mImage.emplace(device, image);
        mSampler.emplace(device, VK_FILTER_LINEAR, VK_SAMPLER_ADDRESS_MODE_REPEAT, "init-fails.sampler");
        // A raw handle only shutdown releases, as a backend's pipelines are:
        // the object tracking reports it unless the host calls shutdown.
        mDevice = &device;
        VkDescriptorSetLayoutCreateInfo layout{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
        vkCreateDescriptorSetLayout(device.handle(), &layout, nullptr, &mLayout);
        device.setName(VK_OBJECT_TYPE_DESCRIPTOR_SET_LAYOUT, mLayout, "init-fails.layout");
        return fail("backend init-fails: the pipeline \"init-fails.draw\" does not build on ", info.features.deviceName,
                    " (a test backend that always fails here)");
    }
    void shutdown() override {
        if (mLayout) {
            mDevice->clearName(VK_OBJECT_TYPE_DESCRIPTOR_SET_LAYOUT, mLayout);
            vkDestroyDescriptorSetLayout(mDevice->handle(), mLayout, nullptr);
            mLayout = VK_NULL_HANDLE;
        }
        mSampler.reset();
        mImage.reset();
        mBuffer.reset();
    }

private:
    std::optional<gpu::Buffer> mBuffer;
    std::optional<gpu::Image> mImage;
    std::optional<gpu::Sampler> mSampler;
    gpu::Device* mDevice = nullptr;
    VkDescriptorSetLayout mLayout = VK_NULL_HANDLE;
};

backend::Backend* create() { return new InitFailsBackend(); }
void destroy(backend::Backend* b) { delete b; }

} // namespace

TESSERA_REGISTER_PLUGIN(registry) { registry.registerBackend({"init-fails", &create, &destroy}); }
