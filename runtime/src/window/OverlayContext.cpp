#include "window/OverlayContext.h"

#include "session/SessionGpu.h"
#include "tessera/gpu/RenderTarget.h"
#include "tessera/runtime/RenderSession.h"
#include "tessera/runtime/Settings.h"

#include <imgui.h>
#include <backends/imgui_impl_glfw.h>

#include <cstring>

namespace tessera::runtime {

static_assert(sizeof(ImDrawVert) == sizeof(gpu::UiVertex), "gpu::UiVertex must match ImDrawVert");
static_assert(sizeof(ImDrawIdx) == sizeof(uint16_t), "the overlay draws 16-bit ImGui indices");

Result<std::unique_ptr<OverlayContext>> OverlayContext::create(RenderSession& session) {
    gpu::Device* device = SessionGpu::device(session);
    if (!device) return failSetting(setting::kOverlay, ": the null backend draws nothing to put an overlay on");
    std::unique_ptr<OverlayContext> overlay(new OverlayContext());
    IMGUI_CHECKVERSION();
    overlay->mContext = ImGui::CreateContext();
    ImGui::SetCurrentContext(overlay->mContext);
    ImGuiIO& io = ImGui::GetIO();
    // No imgui.ini next to wherever the demo was started from.
    io.IniFilename = nullptr;
    io.BackendRendererName = "tessera::gpu::UiRenderer";
    io.BackendFlags |= ImGuiBackendFlags_RendererHasVtxOffset;
    ImGui::StyleColorsDark();
    ImGui::GetStyle().Alpha = 0.92f;
    if (GLFWwindow* window = SessionGpu::window(session)) {
        if (!ImGui_ImplGlfw_InitForVulkan(window, true))
            return failSetting(setting::kWindow, ": the overlay could not bind the window's input");
        overlay->mGlfwBound = true;
    } else {
        // Headless: the target is the display, and nothing gives input.
        overlay->mHeadlessWidth = float(session.width());
        overlay->mHeadlessHeight = float(session.height());
    }

    unsigned char* pixels = nullptr;
    int width = 0, height = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
    const auto target = gpu::RenderTarget::kColorFormat;
    overlay->mRenderer = gpu::UiRenderer(*device, target, gpu::RenderTarget::kDepthFormat, uint32_t(width),
                                         uint32_t(height), {pixels, size_t(width) * size_t(height) * 4});
    io.Fonts->SetTexID(reinterpret_cast<ImTextureID>(uintptr_t(1))); // one texture: any non-null id
    return overlay;
}

OverlayContext::~OverlayContext() {
    if (!mContext) return;
    ImGui::SetCurrentContext(mContext);
    if (mGlfwBound) ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext(mContext);
}

void OverlayContext::beginFrame() {
    ImGui::SetCurrentContext(mContext);
    if (mGlfwBound) {
        ImGui_ImplGlfw_NewFrame();
    } else {
        ImGuiIO& io = ImGui::GetIO();
        io.DisplaySize = ImVec2(mHeadlessWidth, mHeadlessHeight);
        io.DeltaTime = 1.0f / 30.0f; // the flythrough's fixed step
    }
    ImGui::NewFrame();
}

void OverlayContext::endFrame(bool visible) {
    ImGui::Render();
    mVertices.clear();
    mIndices.clear();
    mCommands.clear();
    mData = {};
    const ImDrawData* draw = ImGui::GetDrawData();
    if (!visible || !draw || draw->TotalVtxCount == 0) return;
    // One vertex and one index buffer for every list; each command keeps its
    // list's offsets so the indices stay 16-bit.
    for (int n = 0; n < draw->CmdListsCount; ++n) {
        const ImDrawList* list = draw->CmdLists[n];
        const int32_t vertexBase = int32_t(mVertices.size());
        const uint32_t indexBase = uint32_t(mIndices.size());
        const auto* vertices = reinterpret_cast<const gpu::UiVertex*>(list->VtxBuffer.Data);
        mVertices.insert(mVertices.end(), vertices, vertices + list->VtxBuffer.Size);
        mIndices.insert(mIndices.end(), list->IdxBuffer.Data, list->IdxBuffer.Data + list->IdxBuffer.Size);
        for (const ImDrawCmd& cmd : list->CmdBuffer) {
            if (cmd.UserCallback) continue; // none of ours use callbacks
            gpu::UiDrawCommand c;
            c.clipMinX = cmd.ClipRect.x;
            c.clipMinY = cmd.ClipRect.y;
            c.clipMaxX = cmd.ClipRect.z;
            c.clipMaxY = cmd.ClipRect.w;
            c.firstIndex = indexBase + cmd.IdxOffset;
            c.indexCount = cmd.ElemCount;
            c.vertexOffset = vertexBase + int32_t(cmd.VtxOffset);
            mCommands.push_back(c);
        }
    }
    mData.vertices = mVertices;
    mData.indices = mIndices;
    mData.commands = mCommands;
    mData.displayX = draw->DisplayPos.x;
    mData.displayY = draw->DisplayPos.y;
    mData.displayWidth = draw->DisplaySize.x;
    mData.displayHeight = draw->DisplaySize.y;
}

void OverlayContext::record(gpu::FrameContext& frame) { mRenderer.record(frame, mData); }

bool OverlayContext::wantsMouse() const { return ImGui::GetIO().WantCaptureMouse; }
bool OverlayContext::wantsKeyboard() const { return ImGui::GetIO().WantCaptureKeyboard; }

} // namespace tessera::runtime
