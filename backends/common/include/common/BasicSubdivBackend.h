#pragma once
/// @file BasicSubdivBackend.h
/// The subdivision-surface commands of the contract (the second paper),
/// written once for every GPU backend: the surfaces' table, their uploads
/// (GpuSubdiv), the tile updates, the frame's order of a draw (the cage
/// uploaded, the technique's passes outside the main pass, its draw inside
/// it, the report) and the blocking read of the refined points. A backend
/// that sets BackendCapabilities::subdiv supplies its technique through the
/// hooks below; one that does not refuses createSubdiv.

#include "common/BasicTerrainBackend.h"
#include "common/GpuObjectTable.h"
#include "common/GpuSubdiv.h"

namespace tessera::backends {

class BasicSubdivBackend : public BasicTerrainBackend {
public:
    Result<backend::SubdivHandle> createSubdiv(const backend::SubdivDesc& desc) final;
    void destroySubdiv(backend::SubdivHandle surface) final;
    void updateSubdivTiles(backend::SubdivHandle surface, const backend::SubdivTileData& tiles,
                           std::span<const glm::uvec4> rects) final;
    void drawSubdiv(backend::SubdivHandle surface, const backend::SubdivDrawInfo& draw) final;
    Result<backend::SubdivPoints> readSubdivPoints(backend::SubdivHandle surface) final;

protected:
    // What a backend that draws surfaces supplies (its technique).
    /// How the refine pass writes a surface's refined points (buffer usage:
    /// storage, transform feedback, or transfer from a render target).
    virtual VkBufferUsageFlags subdivWriteUsage() const { return 0; }
    /// Refuses, before anything is made, a surface the technique cannot
    /// draw on this device (a device limit), with a message naming it.
    virtual Status checkSubdiv(const backend::SubdivDesc&) { return {}; }
    /// Attaches the technique's per-surface resources (GpuSubdiv::attach, a
    /// TechniqueExtension) once the surface is made; an error refuses it.
    virtual Status attachSubdivResources(GpuSubdiv& /*surface*/) { return {}; }
    /// Outside the main pass: refines `surface`'s points from the frame
    /// slot's cage (and whatever else the technique prepares: levels,
    /// records, commands), leaving them ready for the draw. `uniforms`
    /// holds this draw's shader::SubdivUniforms.
    virtual void recordSubdivPasses(GpuSubdiv& /*surface*/, const gpu::UniformSlice& /*uniforms*/) {}
    /// Inside the main pass: tessellates, displaces and draws the surface.
    virtual void recordSubdivDraw(GpuSubdiv& /*surface*/, const gpu::UniformSlice& /*uniforms*/) {}

    void releaseObjects() override;

private:
    GpuObjectTable<GpuSubdiv, backend::SubdivHandle> mSubdivs;
};

} // namespace tessera::backends
