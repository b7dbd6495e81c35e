#pragma once
/// @file OverlayPanel.h
/// The window's Dear ImGui windows: what the frame cost and drew (device,
/// backend, CPU and GPU times with per-pass graphs, pipeline statistics,
/// triangles and instances) and the controls (backend, terrain mode,
/// metric and levels, wireframe, LOD colours, crowd size, meteors,
/// displacement, normals, camera, screenshot and capture).

#include "window/FrameStats.h"
#include "window/OverlayActions.h"

#include <string>
#include <vector>

namespace tessera::runtime {

class SceneRun;

/// The camera and status line the controller owns and the panel shows.
struct OverlayState {
    bool freeCamera = false;
    float cameraSpeed = 40.0f;
    uint32_t agents = 0;             ///< the crowd size slider (crowd scene)
    std::string status;              ///< the last action's result, shown once
    std::vector<std::string> backends; ///< the backends this device runs
};

/// Builds this frame's windows (between OverlayContext::beginFrame and
/// endFrame). Settings apply to `run` directly; the rest go to `actions`.
void drawOverlayPanel(SceneRun& run, const FrameStats& stats, OverlayState& state, OverlayActions& actions);

} // namespace tessera::runtime
