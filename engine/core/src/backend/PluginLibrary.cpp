#include "tessera/backend/PluginLibrary.h"

#include "tessera/backend/PluginApi.h"

#include <dlfcn.h>
#include <elf.h>

#include <cstring>
#include <fstream>
#include <string>

namespace tessera::backend {
namespace {

std::string dlerrorText() {
    const char* text = dlerror();
    return text ? text : "unknown dynamic loader error";
}

// dlopen's message for a bad file is terse ("invalid ELF header"); look at the
// file ourselves so the user reads what is actually wrong (Falcor issue #341).
std::string diagnoseOpenFailure(const std::filesystem::path& path, const std::string& dlText) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) return "no such file";
    if (std::filesystem::is_directory(path, ec)) return "it is a directory, not a shared library";
    std::ifstream file(path, std::ios::binary);
    unsigned char ident[EI_NIDENT] = {};
    file.read(reinterpret_cast<char*>(ident), sizeof ident);
    if (file.gcount() < static_cast<std::streamsize>(sizeof ident) || std::memcmp(ident, ELFMAG, SELFMAG) != 0)
        return "not a shared library (no ELF header); dynamic loader said: " + dlText;
    // A dependency that cannot be found is reported by glibc as
    // "<dep>: cannot open shared object file"; name it explicitly.
    const std::string marker = ": cannot open shared object file";
    if (auto pos = dlText.find(marker); pos != std::string::npos) {
        std::string dep = dlText.substr(0, pos);
        if (auto colon = dep.rfind(": "); colon != std::string::npos) dep = dep.substr(colon + 2);
        if (dep != path.string())
            return "a library it depends on was not found: " + dep + " (dynamic loader said: " + dlText +
                   "); check LD_LIBRARY_PATH or install the package that provides it";
    }
    if (dlText.find("undefined symbol") != std::string::npos)
        return "it needs a symbol the host does not provide, probably built against another Tessera "
               "version (dynamic loader said: " + dlText + ")";
    if (dlText.find("wrong ELF class") != std::string::npos)
        return "built for another architecture (dynamic loader said: " + dlText + ")";
    return "the dynamic loader refused it: " + dlText;
}

} // namespace

Result<std::shared_ptr<PluginLibrary>> PluginLibrary::open(const std::filesystem::path& path) {
    dlerror(); // clear stale state
    // RTLD_NOW resolves every symbol at load so a broken plugin fails here, with
    // a message, instead of in the middle of a frame. RTLD_LOCAL keeps plugins
    // from satisfying each other's symbols by accident.
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
        const std::string text = dlerrorText();
        return fail("plugin ", path.string(), ": ", diagnoseOpenFailure(path, text));
    }

    const char* entryName = TESSERA_PLUGIN_STRINGIFY(TESSERA_PLUGIN_ENTRY_SYMBOL);
    void* entry = dlsym(handle, entryName);
    if (!entry) {
        // Look for another version of the entry point to tell an ABI mismatch
        // apart from a module that is not a Tessera plugin at all.
        for (uint32_t v = 0; v < 64; ++v) {
            if (v == kPluginAbiVersion) continue;
            const std::string other = TESSERA_PLUGIN_ENTRY_PREFIX + std::to_string(v);
            if (dlsym(handle, other.c_str())) {
                dlclose(handle);
                return fail("plugin ", path.string(), ": ABI mismatch: it was built for plugin ABI version ",
                            std::to_string(v), " but this host needs version ", std::to_string(kPluginAbiVersion),
                            "; rebuild the plugin against this Tessera");
            }
        }
        dlclose(handle);
        return fail("plugin ", path.string(), ": not a Tessera plugin: it does not export ", entryName);
    }
    return std::shared_ptr<PluginLibrary>(new PluginLibrary(path, handle, entry));
}

PluginLibrary::~PluginLibrary() {
    if (mHandle) dlclose(mHandle);
}

} // namespace tessera::backend
