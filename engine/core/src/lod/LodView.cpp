#include "tessera/lod/LodFrame.h"
#include "tessera/lod/LodInstance.h"

#include <cmath>

namespace tessera::lod {

LodView LodView::fromCamera(const scene::Camera& camera, uint32_t viewportHeight, float maxLevel) {
    LodView view;
    view.frustum = camera.frustum();
    view.eye = camera.position();
    view.pixelsPerRadian = float(viewportHeight) / (2.0f * std::tan(0.5f * camera.verticalFov()));
    view.maxLevel = maxLevel;
    return view;
}

const char* toString(Tier tier) {
    switch (tier) {
    case Tier::Near: return "near";
    case Tier::Middle: return "middle";
    case Tier::Far: return "far";
    case Tier::Impostor: return "impostor";
    }
    return "?";
}

} // namespace tessera::lod
