#pragma once
// Small scenes for the shooting tests, built in-process with the geometry builder library.
#include <cstdint>

#include "runtime/geometry/geometry_file.h"

namespace kdpm::test {

// The closed unit cube [0,1]^3, every face diffuse with grey albedo `rho` (the floor y = 0 a
// mirror when `mirror_floor`), lit by a 0.2 x 0.2 card light at y = 0.9 facing down.
GeometryFile closed_box(float rho, bool mirror_floor = false);

// The same box (albedo rho) with two white card lights: a 0.2 x 0.2 one of radiance 1 at y = 0.9
// facing down, and a 0.1 x 0.1 one of radiance 12 (three times the power) at y = 0.1 facing up.
GeometryFile closed_box_two_lights(float rho);

// closed_box(rho, mirror_floor = true) with a glass cube (ior 1.5, clear) just above the floor
// under the light: paths through it and off the floor store caustic photons.
GeometryFile closed_box_with_glass_cube(float rho);

// A 2000 x 2000 black floor at y = 0 under a 0.01 x 0.01 card light at height h facing down.
GeometryFile floor_under_small_light(float h);

}  // namespace kdpm::test
