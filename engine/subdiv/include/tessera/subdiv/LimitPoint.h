#pragma once
/// @file LimitPoint.h
/// A point of a limit surface with its first and second partial derivatives.

#include <glm/glm.hpp>

namespace tessera::subdiv {

/// Position and partial derivatives of a limit surface at one parameter
/// location, in double precision (the CPU reference a GPU evaluation is
/// compared with). Which parameterization the derivatives are taken in is
/// said by the function that returns it.
struct LimitPoint {
    glm::dvec3 position{0.0};
    glm::dvec3 du{0.0}, dv{0.0};
    /// Second derivatives, for the Weingarten term of displaced normals.
    glm::dvec3 duu{0.0}, duv{0.0}, dvv{0.0};

    /// The unnormalized normal du x dv (zero where the tangents are
    /// parallel, e.g. at a degenerate corner).
    glm::dvec3 normal() const { return glm::cross(du, dv); }
};

} // namespace tessera::subdiv
