#include "GpuTestDevice.h"

#include <gtest/gtest.h>

namespace tessera::test {

namespace {

struct Shared {
    std::unique_ptr<gpu::Instance> instance;
    std::unique_ptr<gpu::Device> device;
    std::string error;
    bool tried = false;
};

Shared& shared() {
    static Shared s;
    return s;
}

// Releases the device and instance after the last test, while the Vulkan
// loader and driver are still loaded (a static destructor would run too late).
class ReleaseDevice : public ::testing::Environment {
public:
    void TearDown() override {
        shared().device.reset();
        shared().instance.reset();
    }
};

[[maybe_unused]] ::testing::Environment* const kReleaseDevice = ::testing::AddGlobalTestEnvironment(new ReleaseDevice);

} // namespace

gpu::Device* GpuTestDevice::get(std::string& why) {
    Shared& s = shared();
    if (!s.tried) {
        s.tried = true;
        gpu::InstanceOptions options;
        options.validation = true;
        auto instance = gpu::Instance::create(options);
        if (!instance) {
            s.error = instance.error().message;
        } else {
            auto physical = instance.value()->selectDevice("");
            if (!physical) {
                s.error = physical.error().message;
            } else {
                auto device = gpu::Device::create(*instance.value(), physical.value());
                if (!device) s.error = device.error().message;
                else s.device = std::move(device.value());
            }
            s.instance = std::move(instance.value());
        }
    }
    why = s.error;
    return s.device.get();
}

} // namespace tessera::test
