#include "tessera/backend/BackendRegistry.h"

namespace tessera::backend {

void BackendDeleter::operator()(Backend* backend) const {
    if (backend && mDestroy) mDestroy(backend);
    // mLibrary is released after the object, so the module's code outlives it.
}

void BackendRegistry::registerBackend(const BackendPluginDesc& desc) {
    const std::string source = mLoading ? mLoading->path().string() : std::string("(built in)");
    if (!desc.name || !*desc.name || !desc.create || !desc.destroy) {
        mErrors.push_back("plugin " + source + ": registered a backend without a name, create or destroy function");
        return;
    }
    if (auto it = mEntries.find(desc.name); it != mEntries.end()) {
        mErrors.push_back("plugin " + source + ": backend name \"" + desc.name + "\" is already registered by " +
                          sourceOf(desc.name));
        return;
    }
    mEntries.emplace(desc.name, Entry{desc, mLoading});
    ++mRegisteredByCurrent;
}

Status BackendRegistry::addPlugin(const std::shared_ptr<PluginLibrary>& library) {
    mLoading = library;
    mErrors.clear();
    mRegisteredByCurrent = 0;
    reinterpret_cast<TesseraPluginEntry>(library->entryPoint())(*this);
    mLoading.reset();
    if (!mErrors.empty()) return Error{mErrors.front()};
    if (mRegisteredByCurrent == 0) return fail("plugin ", library->path().string(), ": registered no backend");
    return {};
}

Status BackendRegistry::addBuiltin(const BackendPluginDesc& desc) {
    mErrors.clear();
    registerBackend(desc);
    if (!mErrors.empty()) return Error{mErrors.front()};
    return {};
}

std::vector<std::string> BackendRegistry::names() const {
    std::vector<std::string> out;
    for (const auto& [name, entry] : mEntries) out.push_back(name);
    return out;
}

std::string BackendRegistry::sourceOf(const std::string& name) const {
    auto it = mEntries.find(name);
    if (it == mEntries.end()) return {};
    return it->second.library ? it->second.library->path().string() : "(built in)";
}

Result<BackendPtr> BackendRegistry::create(const std::string& name) const {
    auto it = mEntries.find(name);
    if (it == mEntries.end()) {
        std::string list;
        for (const auto& n : names()) list += (list.empty() ? "" : ", ") + n;
        return fail("unknown backend \"", name, "\"; available backends: ", list.empty() ? "(none)" : list);
    }
    Backend* backend = it->second.desc.create();
    if (!backend) return fail("backend \"", name, "\" failed to create an instance");
    return BackendPtr(backend, BackendDeleter(it->second.desc.destroy, it->second.library));
}

} // namespace tessera::backend
