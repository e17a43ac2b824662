#include "texture_set.h"

#include "cube_map.h"
#include "fur.h"
#include "patterns.h"
#include "planets.h"
#include "sky.h"

#include <array>
#include <utility>

namespace raylab::texgen {

std::vector<NamedImage> generateAllTextures() {
    std::vector<NamedImage> all;
    // Equirectangular maps are twice as wide as high (360 x 180 degrees).
    PlanetTextures e = earth(512, 256);
    all.push_back({"earth.png", std::move(e.color)});
    all.push_back({"earth_normal.png", std::move(e.normal)});
    PlanetTextures m = moon(256, 128);
    all.push_back({"moon.png", std::move(m.color)});
    all.push_back({"moon_normal.png", std::move(m.normal)});
    all.push_back({"sun.png", sun(256, 128)});
    std::array<Image, 6> sky = skyBox(256);
    for (std::size_t i = 0; i < sky.size(); ++i)
        all.push_back({std::string("sky_") + kCubeFaceNames[i] + ".png", std::move(sky[i])});
    all.push_back({"tiles.png", tiles(256)});
    all.push_back({"marble.png", marble(256)});
    all.push_back({"fur_color.png", furColor(256)});
    all.push_back({"fur_pattern.png", furPattern(128)});
    all.push_back({"fur_fin.png", furFin(128, 64)});
    return all;
}

}  // namespace raylab::texgen
