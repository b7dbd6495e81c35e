#pragma once
/// @file SubdivSource.h
/// What RenderSession::createSubdivs uploads: a scene part with Catmull-Clark
/// surfaces (the --model .obj shapes, SubdivModels; the Catmull-Clark
/// characters, SubdivCharacters).

#include "tessera/backend/SubdivDesc.h"

#include <cstddef>

namespace tessera::runtime {

class SubdivSource {
public:
    virtual ~SubdivSource() = default;
    virtual size_t size() const = 0;
    /// What createSubdiv needs for surface `i` (valid while the source lives).
    virtual backend::SubdivDesc desc(size_t i) const = 0;
    virtual void setHandle(size_t i, backend::SubdivHandle handle) = 0;
};

} // namespace tessera::runtime
