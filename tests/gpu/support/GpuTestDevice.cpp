#include "GpuTestDevice.h"

namespace tessera::test {

namespace {

struct Shared {
    std::unique_ptr<gpu::Instance> instance;
    std::unique_ptr<gpu::Device> device;
    std::string error;
    bool tried = false;
};

Shared& shared() {
    // Leaked on purpose: tests may run in any order and the device must
    // outlive every fixture; the process exit releases it.
    static Shared* s = new Shared();
    return *s;
}

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
