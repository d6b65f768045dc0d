// SPDX-License-Identifier: Apache-2.0
// Bounding spheres for the cluster hierarchy (bake/cluster/cluster_build.hpp): the sphere around a set
// of spheres (a point is a sphere of radius 0). meshopt_computeSphereBounds is not in
// meshoptimizer 0.18, so this is Ritter's (1990) grow pass; the radius is then recomputed about
// the rounded float centre and rounded up, so `sphere_contains` holds for every input exactly.
#pragma once

#include <span>

namespace gazelod::bake {

struct Sphere {
  float x = 0.0f, y = 0.0f, z = 0.0f, radius_m = 0.0f;
};

// Encloses every sphere of `spheres` (finite values, radius >= 0); {0,0,0,0} when empty.
Sphere enclosing_sphere(std::span<const Sphere> spheres);

// |centre distance| + inner radius <= outer radius, in double on the stored floats (the
// arithmetic enclosing_sphere guarantees).
bool sphere_contains(const Sphere& outer, const Sphere& inner);

}  // namespace gazelod::bake
