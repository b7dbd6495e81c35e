#include "tessera/runtime/Options.h"

#include <cstdio>

namespace tessera::runtime {

std::string formatNumber(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

} // namespace tessera::runtime
