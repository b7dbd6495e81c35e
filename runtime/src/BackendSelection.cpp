#include "tessera/runtime/BackendSelection.h"

#include "tessera/runtime/Reporter.h"
#include "tessera/runtime/Settings.h"
#include "tessera/core/Log.h"
#include "tessera/gpu/Swapchain.h"

#include <cstdio>
#include <optional>

namespace tessera::runtime {
namespace {

backend::PluginLoader makeLoader(const Options& options) {
    backend::PluginLoader loader;
    for (const auto& dir : options.pluginDirs) loader.addSearchDirectory(dir);
    return loader;
}

Result<std::unique_ptr<gpu::Instance>> makeInstance(const Options& options) {
    gpu::InstanceOptions io;
    io.validation = options.validation;
    io.windowing = options.window && gpu::Swapchain::initWindowSystem();
    return gpu::Instance::create(io);
}

std::string joinMissing(const backend::BackendCapabilities& caps) {
    std::string out;
    for (const auto& m : caps.missing) out += (out.empty() ? "" : ", ") + m;
    return out;
}

} // namespace

Result<std::unique_ptr<SelectedBackend>> selectBackend(const Options& options) {
    const Reporter& reporter = reporterFor(options);
    auto selected = std::make_unique<SelectedBackend>();
    auto loader = makeLoader(options);

    std::vector<std::string> candidates;
    if (!options.backend.empty()) candidates.push_back(options.backend);
    else candidates.assign(std::begin(kBackendPreference), std::end(kBackendPreference));

    // Load the plugins first: a bad --backend must fail before any device work.
    std::vector<Error> loadErrors;
    for (const auto& name : candidates) {
        if (auto loaded = loader.loadBackend(name, selected->registry); !loaded) {
            if (!options.backend.empty()) return loaded.error();
            loadErrors.push_back(loaded.error());
        }
    }
    if (selected->registry.names().empty())
        return fail("no backend plugin could be loaded: ", loadErrors.empty() ? "none found" : loadErrors.front().message);

    for (const auto& name : candidates) {
        if (!selected->registry.contains(name)) continue;
        auto created = selected->registry.create(name);
        if (!created) return created.error();
        backend::BackendPtr candidate = std::move(created.value());
        auto caps = candidate->capabilities(nullptr);
        if (caps.requiresGpu && !selected->device) {
            auto instance = makeInstance(options);
            if (!instance) return instance.error();
            auto physical = instance.value()->selectDevice(options.device);
            if (!physical) return physical.error();
            // --hide-features: the device as the backends see it and as Device::create enables it.
            device::applyFeatureMask(options.hiddenFeatures, physical.value().features);
            auto device = gpu::Device::create(*instance.value(), physical.value());
            if (!device) return device.error();
            selected->instance = std::move(instance.value());
            selected->device = std::move(device.value());
            selected->device->setMemoryCap(options.deviceMemoryCap);
            if (options.failAllocation) selected->device->failAllocation(*options.failAllocation);
        }
        if (caps.requiresGpu) caps = candidate->capabilities(&selected->device->features());
        if (!caps.supported()) {
            const std::string why =
                " " + name + " cannot run on " + selected->device->features().deviceName + ": it needs " + joinMissing(caps);
            if (!options.backend.empty())
                return failSetting(setting::kBackend, why, "; ", reporter.name(setting::kListBackends),
                                   " to see which backends this device runs");
            log::info(setting::kBackend + why + "; trying the next backend");
            continue;
        }
        if (!caps.requiresGpu && options.deviceMemoryCap)
            reporter.warning(failSetting(setting::kDeviceMemoryCap, ": backend ", name,
                                         " allocates no device memory; the cap does nothing"));
        selected->backend = std::move(candidate);
        selected->capabilities = caps;
        return selected;
    }
    return fail("no backend can run on this device; ", reporter.name(setting::kListBackends), " for details");
}

Result<backend::BackendPtr> createBackendOnDevice(SelectedBackend& selected, const Options& options,
                                                  const std::string& name, backend::BackendCapabilities& caps) {
    if (!selected.registry.contains(name)) {
        if (Status loaded = makeLoader(options).loadBackend(name, selected.registry); !loaded) return loaded.error();
    }
    auto created = selected.registry.create(name);
    if (!created) return created.error();
    const device::DeviceFeatures* features = selected.device ? &selected.device->features() : nullptr;
    caps = created.value()->capabilities(features);
    // A session keeps its device (and window) across switches, so the null
    // backend and the GPU backends cannot replace one another in it.
    if (caps.requiresGpu && !features)
        return fail("backend ", name, " needs a Vulkan device and this session runs the null backend without one; "
                    "start with a GPU backend to switch between them");
    if (!caps.requiresGpu && features)
        return fail("backend ", name, " runs without a device and this session renders on ", features->deviceName,
                    "; start with ", reporterFor(options).name(setting::kBackend), " ", name, " instead");
    if (!caps.supported())
        return fail("backend ", name, " cannot run on ", features ? features->deviceName : std::string("this host"),
                    ": it needs ", joinMissing(caps));
    return std::move(created.value());
}

Status listBackends(const Options& options) {
    auto loader = makeLoader(options);
    backend::BackendRegistry registry;
    for (const auto& error : loader.loadAll(registry)) reporterFor(options).warning(error);

    std::optional<device::DeviceFeatures> deviceFeatures;
    if (auto created = makeInstance(options); created) {
        auto physical = created.value()->selectDevice(options.device);
        if (!physical) return physical.error();
        std::printf("device: %s (%s)\n\n", physical->features.deviceName.c_str(), gpu::deviceTypeName(physical->type));
        deviceFeatures = physical->features;
        device::applyFeatureMask(options.hiddenFeatures, *deviceFeatures);
    } else {
        std::printf("device: none (%s)\n\n", created.error().message.c_str());
    }

    const device::DeviceFeatures* features = deviceFeatures ? &*deviceFeatures : nullptr;
    std::printf("%-11s %-9s %-10s %-4s %-4s %-7s %-6s %s\n", "backend", "status", "tess", "xfb", "geom", "compute",
                "max tf", "description");
    for (const auto& name : registry.names()) {
        auto backend = registry.create(name);
        if (!backend) continue;
        auto caps = backend.value()->capabilities(features);
        const bool runnable = caps.supported() && (features || !caps.requiresGpu);
        std::printf("%-11s %-9s %-10s %-4s %-4s %-7s %-6.2f %s\n", name.c_str(), runnable ? "ok" : "no",
                    backend::toString(caps.tessellation), caps.usesTransformFeedback ? "yes" : "-",
                    caps.usesGeometryShaders ? "yes" : "-", caps.usesCompute ? "yes" : "-", caps.maxTessFactor,
                    caps.description.c_str());
        if (!caps.missing.empty()) std::printf("%-11s missing: %s\n", "", joinMissing(caps).c_str());
        std::printf("%-11s from %s\n", "", registry.sourceOf(name).c_str());
    }
    return {};
}

Status listDevices(const Options& options) {
    auto instance = makeInstance(options);
    if (!instance) return instance.error();
    auto chosen = instance.value()->selectDevice(options.device);
    for (const auto& d : instance.value()->devices()) {
        device::DeviceFeatures f = d.features;
        device::applyFeatureMask(options.hiddenFeatures, f);
        std::printf("%u: %s (%s) driver %s %s%s\n   tessellation %s (max %u), geometry %s, transform feedback %s, "
                    "pipeline statistics %s, timestamps %s\n",
                    d.index, f.deviceName.c_str(), gpu::deviceTypeName(d.type), f.driverName.c_str(), f.driverInfo.c_str(),
                    chosen && chosen->index == d.index ? "  [default]" : "", f.tessellationShader ? "yes" : "no",
                    f.maxTessellationLevel, f.geometryShader ? "yes" : "no", f.transformFeedback ? "yes" : "no",
                    f.pipelineStatistics ? "yes" : "no", f.timestamps ? "yes" : "no");
    }
    return {};
}

uint64_t validationMessages() { return gpu::Instance::validationMessageCount(); }

} // namespace tessera::runtime
