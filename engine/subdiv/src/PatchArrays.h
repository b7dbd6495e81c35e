#pragma once
// Far::PatchTable's patches copied into the plain arrays a GPU uploads
// (PatchData.h), with the handles Far's evaluation needs for each.

#include "tessera/core/Result.h"
#include "tessera/subdiv/PatchData.h"

#include <opensubdiv/far/patchTable.h>

#include <string>
#include <vector>

namespace tessera::subdiv::detail {

namespace Far = OpenSubdiv::Far;

struct PatchArrays {
    std::vector<Patch> patches;
    std::vector<uint32_t> indices;
    std::vector<PatchRange> ranges;
    /// Per patch, Far's handle (array, patch and control-point offset).
    std::vector<Far::PatchTable::PatchHandle> handles;

    /// Copies `table`. Errors (naming `name`): a patch type OsdEvaluatePatchBasis
    /// cannot draw here, or an index outside [0, controlPointCount).
    static Result<PatchArrays> fromTable(const Far::PatchTable& table, uint32_t controlPointCount,
                                         const std::string& name);
};

} // namespace tessera::subdiv::detail
