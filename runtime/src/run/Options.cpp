#include "tessera/runtime/Options.h"

#include <cstdio>

namespace tessera::runtime {

terrain::TessellationSettings TessellationOptions::settings() const {
    terrain::TessellationSettings settings;
    if (metric) settings.metric = *metric;
    settings.targetPixels = targetPixels.value_or(terrain::defaultTargetPixels(settings.metric));
    settings.farDistance = farDistance;
    if (continuousLevel) settings.continuousLevel = *continuousLevel;
    if (maxLevel) settings.maxLevel = *maxLevel;
    return settings;
}

std::string formatNumber(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

} // namespace tessera::runtime
