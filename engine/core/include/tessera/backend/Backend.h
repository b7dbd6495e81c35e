#pragma once
/// @file Backend.h
/// The backend contract: the abstract interface every Tessera backend plugin
/// implements, generated from BackendApi.inc.
///
/// A host drives a backend like this:
/// @code
///   auto caps = backend.capabilities(&features);   // may it run here?
///   backend.initialize(info);
///   auto terrain = backend.createTerrain(desc);
///   for each frame:
///       backend.beginFrame(frame);                  // host owns cmd buffer
///       backend.drawTerrain(*terrain, draw);
///       backend.endFrame();                         // host submits
///   backend.destroyTerrain(*terrain);
///   backend.shutdown();
/// @endcode
/// Calls come from one thread. Handles are only valid on the backend that
/// made them.

#include "tessera/backend/BackendCapabilities.h"
#include "tessera/backend/BackendInitInfo.h"
#include "tessera/backend/CharacterDesc.h"
#include "tessera/backend/CrowdDesc.h"
#include "tessera/device/DeviceFeatures.h"
#include "tessera/backend/FrameInfo.h"
#include "tessera/backend/FrameReport.h"
#include "tessera/backend/Handles.h"
#include "tessera/backend/SubdivDesc.h"
#include "tessera/backend/TerrainDesc.h"
#include "tessera/core/Result.h"

#include <cstdint>
#include <span>
#include <vector>

namespace tessera::backend {

class Backend {
public:
    virtual ~Backend() = default;

#define TESSERA_BACKEND_COMMAND(ReturnType, name, params, args) virtual ReturnType name params = 0;
#include "tessera/backend/BackendApi.inc"
};

} // namespace tessera::backend
