#include "session/SelectedBackend.h"

#include "tessera/runtime/BackendSelection.h"
#include "tessera/runtime/Reporter.h"
#include "tessera/runtime/Settings.h"
#include "tessera/core/Log.h"
#include "tessera/gpu/Swapchain.h"

namespace tessera::runtime {
namespace {

/// The Vulkan instance and the device the options name, with the features
/// they hide masked off and the memory cap and fault injection they ask for.
Status openDevice(const Options& options, SelectedBackend& selected) {
    auto instance = makeInstance(options);
    if (!instance) return instance.error();
    auto physical = instance.value()->selectDevice(options.device);
    if (!physical) return physical.error();
    // --hide-features: the device as the backends see it and as Device::create enables it.
    device::applyFeatureMask(options.hiddenFeatures, physical.value().features);
    auto device = gpu::Device::create(*instance.value(), physical.value());
    if (!device) return device.error();
    selected.instance = std::move(instance.value());
    selected.device = std::move(device.value());
    selected.device->setMemoryCap(options.deviceMemoryCap);
    if (options.failAllocation) selected.device->failAllocation(*options.failAllocation);
    return {};
}

} // namespace

backend::PluginLoader pluginLoaderFor(const Options& options) {
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

Result<std::unique_ptr<SelectedBackend>> selectBackend(const Options& options) {
    const Reporter& reporter = reporterFor(options);
    auto selected = std::make_unique<SelectedBackend>();
    auto loader = pluginLoaderFor(options);

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
        return fail("no backend plugin could be loaded: ",
                    loadErrors.empty() ? "none found" : reporter.wording(loadErrors.front()));
    // Unnamed, the order depends on the device: every preferred backend
    // needs one, so it is opened first.
    if (options.backend.empty()) {
        if (Status ok = openDevice(options, *selected); !ok) return ok.error();
        if (selected->device->features().isCpu)
            candidates.assign(std::begin(kCpuBackendPreference), std::end(kCpuBackendPreference));
    }

    for (const auto& name : candidates) {
        if (!selected->registry.contains(name)) continue;
        auto created = selected->registry.create(name);
        if (!created) return created.error();
        backend::BackendPtr candidate = std::move(created.value());
        auto caps = candidate->capabilities(nullptr);
        if (caps.requiresGpu && !selected->device)
            if (Status ok = openDevice(options, *selected); !ok) return ok.error();
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
        if (Status loaded = pluginLoaderFor(options).loadBackend(name, selected.registry); !loaded) return loaded.error();
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

} // namespace tessera::runtime
