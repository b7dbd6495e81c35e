#include "ShapeRefiner.h"

#include "OsdMessages.h"

#include <opensubdiv/far/topologyDescriptor.h>

#include <cmath>
#include <string>
#include <vector>

namespace tessera::subdiv::detail {

namespace Sdc = OpenSubdiv::Sdc;

namespace {

std::string str(uint64_t value) {
    return std::to_string(value);
}

bool finite(const glm::vec3& p) {
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

bool validSharpness(float s) {
    return std::isfinite(s) && s >= 0.0f;
}

Sdc::Options sdcOptions(const ObjShape& shape) {
    Sdc::Options options;
    switch (shape.boundary) {
    case BoundaryInterpolation::None:
        options.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_NONE);
        break;
    case BoundaryInterpolation::EdgeOnly:
        options.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_ONLY);
        break;
    case BoundaryInterpolation::EdgeAndCorner:
        options.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER);
        break;
    }
    options.SetTriangleSubdivision(shape.smoothTriangles ? Sdc::Options::TRI_SUB_SMOOTH
                                                         : Sdc::Options::TRI_SUB_CATMARK);
    return options;
}

Status validateFaces(const ObjShape& shape) {
    const std::string& name = shape.name;
    uint64_t total = 0;
    for (size_t f = 0; f < shape.faceSizes.size(); ++f) {
        uint32_t size = shape.faceSizes[f];
        if (size < 3) return fail(name, ": face ", str(f), " has ", str(size), " vertices (a face needs at least 3)");
        if (size > kMaxFaceVertices)
            return fail(name, ": face ", str(f), " has ", str(size), " vertices, more than ", str(kMaxFaceVertices));
        total += size;
    }
    if (total != shape.faceVertices.size())
        return fail(name, ": the face sizes add up to ", str(total), " vertices but ", str(shape.faceVertices.size()),
                    " face vertices are given");
    size_t corner = 0;
    for (size_t f = 0; f < shape.faceSizes.size(); ++f) {
        for (uint32_t k = 0; k < shape.faceSizes[f]; ++k, ++corner) {
            uint32_t v = shape.faceVertices[corner];
            if (v >= shape.positions.size())
                return fail(name, ": face ", str(f), " uses vertex ", str(v), " but the shape has ",
                            str(shape.positions.size()), " vertices");
        }
    }
    return {};
}

Status validateTags(const ObjShape& shape) {
    const std::string& name = shape.name;
    const size_t vertices = shape.positions.size();
    for (size_t i = 0; i < shape.creases.size(); ++i) {
        const Crease& c = shape.creases[i];
        if (c.v0 >= vertices || c.v1 >= vertices)
            return fail(name, ": crease ", str(i), " names vertex ", str(std::max(c.v0, c.v1)), " but the shape has ",
                        str(vertices), " vertices");
        if (!validSharpness(c.sharpness))
            return fail(name, ": crease ", str(i), " has a negative or non-finite sharpness");
    }
    for (size_t i = 0; i < shape.corners.size(); ++i) {
        const Corner& c = shape.corners[i];
        if (c.vertex >= vertices)
            return fail(name, ": corner ", str(i), " names vertex ", str(c.vertex), " but the shape has ",
                        str(vertices), " vertices");
        if (!validSharpness(c.sharpness))
            return fail(name, ": corner ", str(i), " has a negative or non-finite sharpness");
    }
    for (uint32_t hole : shape.holes)
        if (hole >= shape.faceSizes.size())
            return fail(name, ": a hole names face ", str(hole), " but the shape has ", str(shape.faceSizes.size()),
                        " faces");
    return {};
}

} // namespace

Status validateShape(const ObjShape& shape, const SubdivSettings& settings) {
    const std::string& name = shape.name;
    if (settings.isolationLevel < 1 || settings.isolationLevel > 10)
        return fail(name, ": isolation level ", str(settings.isolationLevel), " is outside 1 .. 10");
    if (settings.smoothIsolationLevel < 1 || settings.smoothIsolationLevel > settings.isolationLevel)
        return fail(name, ": smooth isolation level ", str(settings.smoothIsolationLevel), " is outside 1 .. ",
                    str(settings.isolationLevel), " (the isolation level)");
    for (size_t v = 0; v < shape.positions.size(); ++v)
        if (!finite(shape.positions[v])) return fail(name, ": vertex ", str(v), " has a non-finite position");
    if (Status faces = validateFaces(shape); !faces) return faces;
    return validateTags(shape);
}

Result<std::unique_ptr<Far::TopologyRefiner>> createRefiner(const ObjShape& shape, const SubdivSettings& settings) {
    // OpenSubdiv takes signed ints; the shape's unsigned indices were range
    // checked, so the copies below are exact.
    std::vector<int> faceSizes(shape.faceSizes.begin(), shape.faceSizes.end());
    std::vector<Far::Index> faceVertices(shape.faceVertices.begin(), shape.faceVertices.end());
    std::vector<Far::Index> creaseVertices;
    std::vector<float> creaseWeights;
    for (const Crease& c : shape.creases) {
        creaseVertices.push_back(Far::Index(c.v0));
        creaseVertices.push_back(Far::Index(c.v1));
        creaseWeights.push_back(c.sharpness);
    }
    std::vector<Far::Index> cornerVertices;
    std::vector<float> cornerWeights;
    for (const Corner& c : shape.corners) {
        cornerVertices.push_back(Far::Index(c.vertex));
        cornerWeights.push_back(c.sharpness);
    }
    std::vector<Far::Index> holes(shape.holes.begin(), shape.holes.end());

    Far::TopologyDescriptor desc;
    desc.numVertices = int(shape.positions.size());
    desc.numFaces = int(faceSizes.size());
    desc.numVertsPerFace = faceSizes.data();
    desc.vertIndicesPerFace = faceVertices.data();
    desc.numCreases = int(creaseWeights.size());
    desc.creaseVertexIndexPairs = creaseVertices.data();
    desc.creaseWeights = creaseWeights.data();
    desc.numCorners = int(cornerWeights.size());
    desc.cornerVertexIndices = cornerVertices.data();
    desc.cornerWeights = cornerWeights.data();
    desc.numHoles = int(holes.size());
    desc.holeIndices = holes.data();

    using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
    OsdMessages messages;
    std::unique_ptr<Far::TopologyRefiner> refiner(
        Factory::Create(desc, Factory::Options(Sdc::SCHEME_CATMARK, sdcOptions(shape))));
    // Topology warnings (a crease on an edge that does not exist, say) are
    // errors here: the surface would silently differ from the file.
    if (!refiner || !messages.empty())
        return fail(shape.name, ": OpenSubdiv cannot build the topology: ",
                    messages.empty() ? std::string("no reason given") : messages.joined());

    Far::TopologyRefiner::AdaptiveOptions adaptive(int(settings.isolationLevel));
    adaptive.SetSecondaryLevel(int(settings.smoothIsolationLevel));
    // Infinitely sharp creases become B-spline boundary patches instead of
    // being isolated to the last level: fewer patches, and exact.
    adaptive.useInfSharpPatch = true;
    // Single-crease patches need a sharpness-aware basis that
    // OsdEvaluatePatchBasis (and Far's EvaluateBasis) do not have.
    adaptive.useSingleCreasePatch = false;
    refiner->RefineAdaptive(adaptive);
    if (!messages.empty()) return fail(shape.name, ": OpenSubdiv cannot refine the topology: ", messages.joined());
    return refiner;
}

} // namespace tessera::subdiv::detail
