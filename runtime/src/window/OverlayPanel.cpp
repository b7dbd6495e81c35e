#include "window/OverlayPanel.h"

#include "tessera/runtime/SceneRun.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <vector>

namespace tessera::runtime {
namespace {

constexpr float kPassBarWidth = 160.0f;

void plotHistory(const char* label, const std::deque<float>& history, const char* overlay) {
    std::vector<float> values(history.begin(), history.end());
    const float top = values.empty() ? 1.0f : *std::max_element(values.begin(), values.end()) * 1.2f;
    ImGui::PlotLines(label, values.data(), int(values.size()), 0, overlay, 0.0f, std::max(top, 0.1f), ImVec2(0, 48));
}

void drawFrameSection(SceneRun& run, const FrameStats& stats) {
    RenderSession& session = run.session();
    ImGui::Text("%s", session.deviceName().c_str());
    ImGui::TextDisabled("%s", session.driverName().c_str());
    ImGui::Text("backend %s, %ux%u", session.capabilities().name.c_str(), session.width(), session.height());
    const float cpu = stats.cpuMeanMs();
    ImGui::Text("CPU frame %.2f ms (%.0f fps)   GPU %.3f ms", cpu, cpu > 0.0f ? 1000.0f / cpu : 0.0f, stats.gpuMs());
    char overlay[64];
    std::snprintf(overlay, sizeof overlay, "CPU %.2f ms", stats.cpuMs());
    plotHistory("##cpu", stats.cpuHistory(), overlay);
    std::snprintf(overlay, sizeof overlay, "GPU %.3f ms", stats.gpuMs());
    plotHistory("##gpu", stats.gpuHistory(), overlay);
    if (!ImGui::TreeNodeEx("GPU passes", ImGuiTreeNodeFlags_DefaultOpen)) return;
    const float total = std::max(stats.gpuMs(), 1e-6f);
    for (const auto& pass : stats.passes()) {
        char text[96];
        std::snprintf(text, sizeof text, "%.3f ms", pass.ms);
        ImGui::ProgressBar(pass.ms / total, ImVec2(kPassBarWidth, 0.0f), text);
        ImGui::SameLine();
        ImGui::TextUnformatted(pass.name.c_str());
    }
    if (stats.passes().empty()) ImGui::TextDisabled("no timestamps from this device yet");
    ImGui::TreePop();
}

void drawCountsSection(SceneRun& run, const FrameStats& stats) {
    const backend::FrameReport report = run.session().lastFrameReport();
    ImGui::Text("terrain patches %u, triangles submitted %llu", report.terrainPatchesDrawn,
                static_cast<unsigned long long>(report.trianglesSubmitted));
    if (report.charactersDrawn)
        ImGui::Text("characters %u, tessellated triangles %llu", report.charactersDrawn,
                    static_cast<unsigned long long>(report.characterTriangles));
    if (run.instancedCrowd())
        ImGui::Text("crowd instances near %u, middle %u, far %u, impostor %u", report.crowdInstances[0],
                    report.crowdInstances[1], report.crowdInstances[2], report.crowdInstances[3]);
    if (report.subdivDomains) ImGui::Text("subdivision domains %u", report.subdivDomains);
    ImGui::Text("intermediate memory %.1f MiB, %u passes", double(report.intermediateBytes) / 1048576.0, report.passes);
    if (!stats.hasStatistics()) return;
    const auto& s = stats.statistics();
    ImGui::Text("pipeline statistics (all passes):");
    ImGui::Text("  vertex shader %llu, tess. eval. %llu, geometry %llu",
                static_cast<unsigned long long>(s.vertexShaderInvocations),
                static_cast<unsigned long long>(s.tessEvaluationInvocations),
                static_cast<unsigned long long>(s.geometryShaderInvocations));
    ImGui::Text("  clipped primitives %llu, fragment shader %llu, compute %llu",
                static_cast<unsigned long long>(s.clippingPrimitives),
                static_cast<unsigned long long>(s.fragmentShaderInvocations),
                static_cast<unsigned long long>(s.computeShaderInvocations));
    if (s.taskShaderInvocations || s.meshShaderInvocations)
        ImGui::Text("  task shader %llu, mesh shader %llu, mesh primitives %llu",
                    static_cast<unsigned long long>(s.taskShaderInvocations),
                    static_cast<unsigned long long>(s.meshShaderInvocations),
                    static_cast<unsigned long long>(s.meshPrimitivesGenerated));
}

void drawTerrainControls(SceneRun& run) {
    const auto& caps = run.session().capabilities();
    terrain::TessellationSettings& t = run.tessellation();
    for (auto mode : {terrain::TerrainMode::LowRes, terrain::TerrainMode::Continuous, terrain::TerrainMode::Adaptive}) {
        if (!caps.drawsTerrainMode(mode)) continue;
        ImGui::SameLine(); // after the "terrain" label, then after each other
        if (ImGui::RadioButton(terrain::toString(mode), t.mode == mode)) t.mode = mode;
    }
    const float top = caps.maxTessFactor;
    if (t.mode == terrain::TerrainMode::Continuous) ImGui::SliderFloat("level", &t.continuousLevel, 1.0f, top, "%.2f");
    if (t.mode != terrain::TerrainMode::Adaptive) return;
    int metric = int(t.metric);
    const char* metrics[] = {terrain::toString(terrain::TessMetric::ScreenEdge),
                             terrain::toString(terrain::TessMetric::Distance),
                             terrain::toString(terrain::TessMetric::Silhouette),
                             terrain::toString(terrain::TessMetric::HeightDetail)};
    if (ImGui::Combo("metric", &metric, metrics, 4)) {
        t.metric = terrain::TessMetric(metric);
        t.targetPixels = terrain::defaultTargetPixels(t.metric);
    }
    if (t.metric == terrain::TessMetric::Distance) ImGui::SliderFloat("far (m)", &t.farDistance, 200.0f, 20000.0f, "%.0f");
    else ImGui::SliderFloat("target (px)", &t.targetPixels, 1.0f, 64.0f, "%.1f");
    ImGui::SliderFloat("min level", &t.minLevel, 1.0f, top, "%.2f");
    ImGui::SliderFloat("max level", &t.maxLevel, 1.0f, top, "%.2f");
    t.minLevel = std::min(t.minLevel, t.maxLevel);
}

void drawControls(SceneRun& run, OverlayState& state, OverlayActions& actions) {
    const std::string current = run.session().capabilities().name;
    if (ImGui::BeginCombo("backend (1-3)", current.c_str())) {
        for (const auto& name : state.backends)
            if (ImGui::Selectable(name.c_str(), name == current) && name != current) actions.switchBackend = name;
        ImGui::EndCombo();
    }
    ImGui::TextUnformatted("terrain");
    drawTerrainControls(run);
    Options& o = run.liveOptions();
    ImGui::Checkbox("wireframe (F2)", &o.wireframe);
    ImGui::SameLine();
    ImGui::Checkbox("LOD colours (F3)", &o.lodColors);
    ImGui::Checkbox("displacement", &o.displacement);
    int normals = int(o.subdiv.normals);
    ImGui::SameLine();
    ImGui::Combo("normals", &normals, "approximate\0accurate\0");
    o.subdiv.normals = uint32_t(normals);
    if (run.world().simulatedCrowd()) {
        int agents = int(state.agents);
        ImGui::SliderInt("agents", &agents, 1, 65000, "%d", ImGuiSliderFlags_Logarithmic);
        state.agents = uint32_t(std::max(agents, 1));
        ImGui::SameLine();
        if (ImGui::Button("apply")) actions.agents = state.agents;
    }
    if (ImGui::Button("drop meteor (M)")) actions.dropMeteor = true;
    ImGui::SameLine();
    ImGui::Checkbox("free camera (Tab)", &state.freeCamera);
    if (state.freeCamera) ImGui::SliderFloat("speed (m/s)", &state.cameraSpeed, 1.0f, 500.0f, "%.0f", ImGuiSliderFlags_Logarithmic);
    if (ImGui::Button("screenshot (F12)")) actions.screenshot = true;
    ImGui::SameLine();
    if (ImGui::Button("RenderDoc capture (F11)")) actions.capture = true;
}

} // namespace

void drawOverlayPanel(SceneRun& run, const FrameStats& stats, OverlayState& state, OverlayActions& actions) {
    ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSizeConstraints(ImVec2(360, 0), ImVec2(520, 2000));
    ImGui::Begin("Tessera", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
    // Tab is the free camera's key, not the panel's focus cycling: with it a
    // Tab could put a slider into text entry and take the keyboard.
    ImGui::PushAllowKeyboardFocus(false);
    drawFrameSection(run, stats);
    if (ImGui::CollapsingHeader("Counts", ImGuiTreeNodeFlags_DefaultOpen)) drawCountsSection(run, stats);
    if (ImGui::CollapsingHeader("Controls", ImGuiTreeNodeFlags_DefaultOpen)) drawControls(run, state, actions);
    ImGui::TextDisabled("F1 overlay  Tab camera  WASD/QE move  right mouse look  Shift fast  Esc quit");
    if (!state.status.empty()) ImGui::TextWrapped("%s", state.status.c_str());
    ImGui::PopAllowKeyboardFocus();
    ImGui::End();
}

} // namespace tessera::runtime
