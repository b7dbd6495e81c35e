#include "tessera/gpu/VulkanCheck.h"

#include "tessera/core/Log.h"

#include <cstdio>
#include <cstdlib>
#include <string>

namespace tessera::gpu {

const char* resultName(VkResult result) {
    switch (result) {
#define TESSERA_RESULT_CASE(r) case r: return #r;
        TESSERA_RESULT_CASE(VK_SUCCESS)
        TESSERA_RESULT_CASE(VK_NOT_READY)
        TESSERA_RESULT_CASE(VK_TIMEOUT)
        TESSERA_RESULT_CASE(VK_INCOMPLETE)
        TESSERA_RESULT_CASE(VK_SUBOPTIMAL_KHR)
        TESSERA_RESULT_CASE(VK_ERROR_OUT_OF_HOST_MEMORY)
        TESSERA_RESULT_CASE(VK_ERROR_OUT_OF_DEVICE_MEMORY)
        TESSERA_RESULT_CASE(VK_ERROR_INITIALIZATION_FAILED)
        TESSERA_RESULT_CASE(VK_ERROR_DEVICE_LOST)
        TESSERA_RESULT_CASE(VK_ERROR_MEMORY_MAP_FAILED)
        TESSERA_RESULT_CASE(VK_ERROR_LAYER_NOT_PRESENT)
        TESSERA_RESULT_CASE(VK_ERROR_EXTENSION_NOT_PRESENT)
        TESSERA_RESULT_CASE(VK_ERROR_FEATURE_NOT_PRESENT)
        TESSERA_RESULT_CASE(VK_ERROR_INCOMPATIBLE_DRIVER)
        TESSERA_RESULT_CASE(VK_ERROR_TOO_MANY_OBJECTS)
        TESSERA_RESULT_CASE(VK_ERROR_FORMAT_NOT_SUPPORTED)
        TESSERA_RESULT_CASE(VK_ERROR_SURFACE_LOST_KHR)
        TESSERA_RESULT_CASE(VK_ERROR_OUT_OF_DATE_KHR)
#undef TESSERA_RESULT_CASE
    default: return "VK_ERROR_(unknown)";
    }
}

void fatalVulkanError(const char* what, VkResult result) {
    log::error(std::string(what) + " failed: " + resultName(result));
    std::fflush(stderr);
    // _Exit: static destructors would call into a device that is already broken.
    std::_Exit(3);
}

} // namespace tessera::gpu
