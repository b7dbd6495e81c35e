#include "PatchArrays.h"

#include <optional>

namespace tessera::subdiv::detail {

namespace {

std::optional<PatchType> patchTypeOf(Far::PatchDescriptor::Type type) {
    switch (type) {
    case Far::PatchDescriptor::REGULAR:
        return PatchType::Regular;
    case Far::PatchDescriptor::GREGORY_BASIS:
        return PatchType::GregoryBasis;
    default:
        return std::nullopt;
    }
}

} // namespace

Result<PatchArrays> PatchArrays::fromTable(const Far::PatchTable& table, uint32_t controlPointCount,
                                           const std::string& name) {
    PatchArrays out;
    for (int array = 0; array < table.GetNumPatchArrays(); ++array) {
        const Far::PatchDescriptor desc = table.GetPatchArrayDescriptor(array);
        const std::optional<PatchType> type = patchTypeOf(desc.GetType());
        if (!type || uint32_t(desc.GetNumControlVertices()) != controlPointsOf(*type))
            return fail(name, ": OpenSubdiv made patches of type ", std::to_string(int(desc.GetType())),
                        ", which the tessellation does not draw");
        const int count = table.GetNumPatches(array);
        if (count == 0) continue;
        const int size = desc.GetNumControlVertices();
        PatchRange range{*type, uint32_t(out.patches.size()), uint32_t(count), uint32_t(out.indices.size())};
        for (int p = 0; p < count; ++p) {
            Far::PatchTable::PatchHandle handle;
            handle.arrayIndex = array;
            handle.patchIndex = Far::Index(out.patches.size());
            handle.vertIndex = p * size; // relative to the array, as Far's own PatchMap sets it
            const Far::ConstIndexArray points = table.GetPatchVertices(array, p);
            const Far::PatchParam param = table.GetPatchParam(array, p);
            Patch patch{*type, uint32_t(out.indices.size()), PatchParam{param.field0, param.field1, 0.0f}};
            for (int i = 0; i < points.size(); ++i) {
                if (points[i] < 0 || uint32_t(points[i]) >= controlPointCount)
                    return fail(name, ": OpenSubdiv patch ", std::to_string(handle.patchIndex), " names control point ",
                                std::to_string(points[i]), " of ", std::to_string(controlPointCount));
                out.indices.push_back(uint32_t(points[i]));
            }
            out.patches.push_back(patch);
            out.handles.push_back(handle);
        }
        out.ranges.push_back(range);
    }
    return out;
}

} // namespace tessera::subdiv::detail
