#pragma once
// From an ObjShape to OpenSubdiv's adaptively refined TopologyRefiner: the
// checks OpenSubdiv leaves to its caller (it trusts indices and counts),
// then OpenSubdiv's own topology checks, reported as one-line Results.

#include "tessera/core/Result.h"
#include "tessera/subdiv/ObjShape.h"
#include "tessera/subdiv/SubdivSettings.h"

#include <opensubdiv/far/topologyRefiner.h>

#include <memory>

namespace tessera::subdiv::detail {

namespace Far = OpenSubdiv::Far;

/// Checks counts, indices, face sizes and finiteness (OpenSubdiv would read
/// out of bounds or build NaN patches) and the settings' ranges.
Status validateShape(const ObjShape& shape, const SubdivSettings& settings);

/// The shape's Catmark refiner, refined feature-adaptively as `settings`
/// say (infinitely sharp patches on, single-crease patches off). Errors
/// carry OpenSubdiv's messages. `shape` must have passed validateShape.
Result<std::unique_ptr<Far::TopologyRefiner>> createRefiner(const ObjShape& shape, const SubdivSettings& settings);

} // namespace tessera::subdiv::detail
