#include "tessera/core/ModulePath.h"

#include <dlfcn.h>

namespace tessera {

std::filesystem::path moduleDirectory(const void* address) {
    Dl_info info{};
    // dladdr names the module the loader mapped the address from; unlike
    // /proc/self/exe it finds libtessera_*.so, not the game's executable.
    if (dladdr(address, &info) == 0 || info.dli_fname == nullptr || info.dli_fname[0] == '\0') return {};
    std::error_code ec;
    const std::filesystem::path file = std::filesystem::canonical(info.dli_fname, ec);
    return ec ? std::filesystem::path() : file.parent_path();
}

} // namespace tessera
