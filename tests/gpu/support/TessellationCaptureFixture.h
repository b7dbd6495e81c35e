#pragma once
/// @file TessellationCaptureFixture.h
/// Test support: a gtest fixture holding the shared GPU test device and a
/// TessellationCapture on it. Skips when the device lacks tessellation,
/// transform feedback or pipeline statistics; fails on any validation message.

#include "GpuTestDevice.h"
#include "TessellationCapture.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>

namespace tessera::test {

class TessellationCaptureFixture : public ::testing::Test {
protected:
    void SetUp() override {
        std::string why;
        device = GpuTestDevice::get(why);
        if (!device) GTEST_SKIP() << "no Vulkan device: " << why;
        const auto& f = device->features();
        if (!f.tessellationShader || !f.transformFeedback || !f.pipelineStatistics)
            GTEST_SKIP() << f.deviceName << " lacks tessellation, transform feedback or pipeline statistics";
        capture = std::make_unique<TessellationCapture>(*device);
    }
    void TearDown() override {
        capture.reset();
        EXPECT_EQ(GpuTestDevice::validationMessages(), 0u);
    }
    gpu::Device* device = nullptr;
    std::unique_ptr<TessellationCapture> capture;
};

} // namespace tessera::test
