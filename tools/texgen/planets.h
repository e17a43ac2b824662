#pragma once
// Planet surfaces in the equirectangular layout of sphere_map.h. Every value
// is a function of the point on the unit sphere, never of (u, v) directly.
#include "image.h"

namespace raylab::texgen {

struct PlanetTextures {
    Image color;
    Image normal;  // encoding in normal_map.h
};

// Oceans (shallower near coasts), green and brown land, deserts, mountains
// with snow, ice caps; the normal map lifts mountains, the sea stays flat.
PlanetTextures earth(int width, int height);

// Grey highlands, darker maria, craters of many sizes (bowls, raised rims).
PlanetTextures moon(int width, int height);

// Yellow-orange granulation; no normal map (the sun is drawn emissive).
Image sun(int width, int height);

}  // namespace raylab::texgen
