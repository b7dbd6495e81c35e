#include "common/BasicSubdivBackend.h"

#include "tessera/core/Log.h"
#include "tessera/gpu/FrameContext.h"

namespace tessera::backends {

Result<backend::SubdivHandle> BasicSubdivBackend::createSubdiv(const backend::SubdivDesc& desc) {
    if (!capabilities(nullptr).subdiv)
        return fail("backend ", capabilities(nullptr).name,
                    " draws no subdivision surfaces (BackendCapabilities::subdiv)");
    if (!mDevice) return fail("createSubdiv before initialize");
    if (Status supported = checkSubdiv(desc); !supported) return supported.error();
    auto created = GpuSubdiv::create(*mDevice, desc, subdivWriteUsage());
    if (!created) return created.error();
    return mSubdivs.add(*mDevice, std::move(created.value()),
                        [this](GpuSubdiv& surface, backend::SubdivHandle) { return attachSubdivResources(surface); });
}

void BasicSubdivBackend::destroySubdiv(backend::SubdivHandle surface) {
    if (mDevice) mSubdivs.destroy(*mDevice, surface);
}

void BasicSubdivBackend::updateSubdivTiles(backend::SubdivHandle surface, const backend::SubdivTileData& tiles,
                                           std::span<const glm::uvec4> rects) {
    GpuSubdiv* s = mSubdivs.find(surface);
    if (!s || rects.empty()) return;
    suspendMainPass();
    if (Status updated = s->updateTiles(*mFrame, tiles, rects); !updated) log::error(updated.error().message);
}

void BasicSubdivBackend::drawSubdiv(backend::SubdivHandle surface, const backend::SubdivDrawInfo& draw) {
    GpuSubdiv* s = mSubdivs.find(surface);
    if (!s) return;
    s->uploadCage(mFrame->slot(), draw.cage);
    const gpu::UniformSlice uniforms = mFrame->pushUniform(draw.uniforms);
    suspendMainPass();
    recordSubdivPasses(*s, uniforms);
    ensureMainPass();
    recordSubdivDraw(*s, uniforms);
    mReport.subdivDomains += s->domainCount();
    mReport.intermediateBytes += s->bytes() + s->extensionBytes();
    mReport.passes += 2;
}

Result<backend::SubdivPoints> BasicSubdivBackend::readSubdivPoints(backend::SubdivHandle surface) {
    GpuSubdiv* s = mSubdivs.find(surface);
    if (!s) return fail("readSubdivPoints: no such surface");
    return backend::SubdivPoints{s->readPoints()};
}

void BasicSubdivBackend::releaseObjects() {
    mSubdivs.clear();
    BasicTerrainBackend::releaseObjects();
}

} // namespace tessera::backends
