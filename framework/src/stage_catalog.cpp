#include "stage_catalog.h"

#include "error.h"
#include "paths.h"

#include <algorithm>

namespace raylab {

namespace {

std::vector<StageInfo> makeStages() {
    std::vector<StageInfo> stages;

    StageInfo raycast;
    raycast.id = "01-raycast";
    raycast.title = "ray casting: primary rays, ray-sphere intersection, nearest hit, flat colours";
    raycast.scene = "stage01.json";
    raycast.checkViews = {
        {"front", std::nullopt, 0.0f, "the scene camera: overlapping spheres at several depths"},
        {"close-overlap", CameraPose{{1.9f, 1.1f, 3.2f}, -28.0f, -8.0f}, 0.0f,
         "spheres in front of one another: only the nearest root of the nearest sphere may win"},
        {"hidden", CameraPose{{5.0f, 1.2f, 3.0f}, 0.0f, -2.0f}, 0.0f,
         "a small sphere inside a big one stays hidden: the nearest root wins, not the far one"},
        {"inside", CameraPose{{5.0f, 1.0f, -2.4f}, 0.0f, 0.0f}, 0.0f,
         "camera inside a large sphere: the near root is behind the eye, the far one is the hit"},
        {"among", CameraPose{{0.2f, 1.3f, -4.0f}, 180.0f, -4.0f}, 0.0f,
         "spheres behind the camera must not be seen (t > 0)"},
        {"moving", std::nullopt, 1.3f, "time 1.3 s: the white sphere has moved"},
    };
    stages.push_back(raycast);

    StageInfo shading;
    shading.id = "02-shading";
    shading.title = "Blinn-Phong shading: ambient once, diffuse and specular from three point lights, a material table";
    shading.scene = "stage02.json";
    shading.checkViews = {
        {"front", std::nullopt, 0.0f, "the scene camera: every sphere lit by three lights"},
        {"highlights", CameraPose{{1.6f, 1.9f, 3.6f}, -18.0f, -14.0f}, 0.0f,
         "close to shiny spheres: the size and place of the highlights (half vector, exponent)"},
        {"dark-side", CameraPose{{-1.5f, 1.6f, -6.5f}, 160.0f, -6.0f}, 0.0f,
         "the sides facing away from the lights: ambient only, no negative light"},
        {"inside", CameraPose{{5.0f, 1.0f, -2.4f}, 0.0f, 0.0f}, 0.0f,
         "camera inside a large sphere: its inside is lit with the normal facing the eye"},
        {"moving", std::nullopt, 1.3f, "time 1.3 s: the white sphere has moved, its shading with it"},
    };
    stages.push_back(shading);

    StageInfo shadows;
    shadows.id = "03-shadows";
    shadows.title = "shadows: a ray toward each light, started just off the surface on the correct side";
    shadows.scene = "stage02.json";
    shadows.checkViews = {
        {"front", std::nullopt, 0.0f, "the scene camera: spheres shadow each other"},
        {"shadow-closeup", CameraPose{{2.6f, 1.5f, 3.2f}, -40.0f, -12.0f}, 0.0f,
         "close to shadows cast by one sphere on another, from three lights"},
        {"grazing", CameraPose{{-4.5f, 1.4f, 1.5f}, 115.0f, -4.0f}, 0.0f,
         "surfaces lit at a grazing angle, where a badly started shadow ray hits its own surface"},
        {"beyond-light", CameraPose{{-3.5f, 4.5f, 5.0f}, 35.0f, -30.0f}, 0.0f,
         "a sphere behind a light must not shadow anything: only blockers closer than the light count"},
        {"shadows-off", std::nullopt, 0.0f, "key 1: with shadows off every light reaches every point", false},
    };
    stages.push_back(shadows);

    StageInfo recursion;
    recursion.id = "04-recursion";
    recursion.title = "reflection and refraction (Fresnel, total internal reflection, gold) with an explicit stack instead of recursion";
    recursion.scene = "stage04.json";
    recursion.checkViews = {
        {"front", std::nullopt, 0.0f, "the scene camera, depth 8: glass, mirror and gold"},
        {"depth-1", std::nullopt, 0.0f, "depth 1: primary rays only, no reflection or refraction", true, 1},
        {"depth-2", std::nullopt, 0.0f, "depth 2: one bounce; mirrors in mirrors stay dark", true, 2},
        {"glass-closeup", CameraPose{{0.4f, 1.3f, 4.0f}, 0.0f, -6.0f}, 0.0f,
         "through the glass sphere: refraction in and out, Fresnel at the rim"},
        {"inside-glass", CameraPose{{0.0f, 1.0f, 1.6f}, 20.0f, 0.0f}, 0.0f,
         "camera inside the glass: leaving the glass, index inverted, total internal reflection"},
        {"gold", CameraPose{{3.6f, 1.6f, 1.6f}, -30.0f, -12.0f}, 0.0f, "the gold sphere: conductor Fresnel per colour channel"},
    };
    stages.push_back(recursion);

    StageInfo primitives;
    primitives.id = "05-primitives";
    primitives.title = "more kinds of object: planes, discs, triangles (Moller-Trumbore), a glass cube and a torus (quartic)";
    primitives.scene = "stage05.json";
    primitives.maxPlanes = 4;
    primitives.maxDiscs = 4;
    primitives.maxTriangles = 32;
    primitives.maxTori = 2;
    primitives.checkViews = {
        {"front", std::nullopt, 0.0f, "the scene camera: floor, disc, mirror rectangle, glass cube with the torus"},
        {"floor-level", CameraPose{{-3.0f, 0.25f, 6.0f}, 20.0f, 1.0f}, 0.0f,
         "eye just above the floor: the plane toward the horizon, rays almost parallel to it"},
        {"from-below", CameraPose{{1.0f, -1.5f, 6.0f}, 0.0f, 12.0f}, 0.0f,
         "eye under the floor: the plane from behind, objects hidden above it"},
        {"disc-closeup", CameraPose{{2.2f, 1.6f, 2.6f}, -20.0f, -5.0f}, 0.0f, "the disc's round edge, against the floor"},
        {"mirror-back", CameraPose{{-5.0f, 1.8f, -7.0f}, 200.0f, -5.0f}, 0.0f,
         "the mirror rectangle from behind: both sides of a triangle count"},
        {"cube-closeup", CameraPose{{1.6f, 1.9f, 3.2f}, -25.0f, -14.0f}, 0.0f,
         "the glass cube: its triangles' edges and inside faces, refraction through it"},
        {"torus-closeup", CameraPose{{0.6f, 1.5f, 2.4f}, -10.0f, -10.0f}, 2.0f,
         "the torus through the glass, turned: the quartic's roots and the torus normal"},
    };
    stages.push_back(primitives);

    StageInfo textures = primitives;
    textures.id = "06-textures";
    textures.title = "textures: sphere and plane texture coordinates, a cube-map sky box, the glow around the sun";
    textures.scene = "stage06.json";
    textures.maxTextures = 8;
    textures.skyBox = true;
    textures.checkViews = {
        {"front", std::nullopt, 0.0f, "the scene camera: earth, moon, tiled floor, marble disc, sky box, sun glow"},
        {"earth-closeup", CameraPose{{-1.0f, 2.0f, 3.4f}, -5.0f, -8.0f}, 0.0f,
         "close to the earth: longitude and latitude, the picture the right way round"},
        {"moon-closeup", CameraPose{{1.6f, 2.0f, 3.3f}, -8.0f, -10.0f}, 0.0f, "close to the moon, seen from another side"},
        {"floor-closeup", CameraPose{{0.5f, 1.0f, 4.0f}, 30.0f, -30.0f}, 0.0f, "the tiled floor: tiles repeat, square, not mirrored"},
        {"sky-up", CameraPose{{0.0f, 2.0f, 5.0f}, 60.0f, 50.0f}, 0.0f, "looking up: only the sky box"},
        {"sun-glow", CameraPose{{0.0f, 2.0f, 5.0f}, 27.0f, 12.0f}, 0.0f, "looking at the sun: its texture and the glow around it"},
        {"sun-behind-moon", CameraPose{{-0.13f, 0.92f, 4.14f}, 29.0f, 13.0f}, 0.0f,
         "the moon in front of the sun: no glow over objects nearer than the sun"},
        {"glow-off", CameraPose{{0.0f, 2.0f, 5.0f}, 27.0f, 12.0f}, 0.0f, "key G: the same without the glow", true, 8, false},
    };
    stages.push_back(textures);

    StageInfo normalMaps = textures;
    normalMaps.id = "07-normalmaps";
    normalMaps.title = "normal mapping: mountains and craters from a picture of normals, in the sphere's tangent frame";
    normalMaps.checkViews = {
        {"front", std::nullopt, 0.0f, "the scene camera: bumpy earth and moon"},
        {"earth-closeup", CameraPose{{-1.0f, 2.0f, 3.4f}, -5.0f, -8.0f}, 0.0f,
         "close to the earth: mountains lit from the side, shading the right way round"},
        {"earth-terminator", CameraPose{{-4.2f, 2.2f, 1.4f}, 65.0f, -10.0f}, 0.0f,
         "where day turns to night on the earth: bumps are strongest in grazing light"},
        {"moon-closeup", CameraPose{{1.6f, 2.0f, 3.3f}, -8.0f, -10.0f}, 0.0f, "close to the moon: craters"},
        {"normal-maps-off", CameraPose{{-1.0f, 2.0f, 3.4f}, -5.0f, -8.0f}, 0.0f, "key N: smooth spheres again", true, 8, true, false},
    };
    stages.push_back(normalMaps);

    StageInfo full = normalMaps;
    full.id = "08-full";
    full.title = "the full demo: lite and pro scenes, every feature, colour modes";
    full.scene = "lite.json";
    full.maxSpheres = 128;
    full.maxMaterials = 32;
    const CameraPose cubeCloseup{{0.2f, 3.0f, 2.6f}, 0.0f, -35.0f};
    full.checkViews = {
        {"lite-front", std::nullopt, 0.0f, "the lite scene: every kind of object, textures, normal maps, glow"},
        {"lite-moving", std::nullopt, 2.5f, "time 2.5 s: the moon and the blue sphere have moved"},
        {"lite-depth-2", std::nullopt, 0.0f, "depth 2: one bounce", true, 2},
        {"lite-shadows-off", std::nullopt, 0.0f, "key 1: shadows off", false},
        {"lite-brb", std::nullopt, 0.0f, "colour mode BRB (Up/Down)", true, 8, true, true, 1},
        {"lite-brr", std::nullopt, 0.0f, "colour mode BRR", true, 8, true, true, 2},
        {"lite-rbb", std::nullopt, 0.0f, "colour mode RBB", true, 8, true, true, 3},
        {"lite-ggr", std::nullopt, 0.0f, "colour mode GGR", true, 8, true, true, 4},
        {"pro-front", std::nullopt, 0.0f, "the pro scene: 110 spheres, the glass cube and the torus", true, 8, true, true, 0, "pro.json"},
        {"pro-cube", cubeCloseup, 1.0f, "the torus inside the glass cube", true, 8, true, true, 0, "pro.json"},
    };
    stages.push_back(full);
    return stages;
}

std::string stageList() {
    std::string list;
    for (const StageInfo& s : allStages()) list += (list.empty() ? "" : ", ") + s.id;
    return list;
}

} // namespace

std::vector<std::string> StageInfo::defines() const {
    auto size = [](const char* name, int limit) { return std::string(name) + " " + std::to_string(std::max(1, limit)); };
    std::vector<std::string> all = {size("MAX_SPHERES", maxSpheres), size("MAX_MATERIALS", maxMaterials), size("MAX_LIGHTS", maxLights),
                                    size("MAX_PLANES", maxPlanes),   size("MAX_DISCS", maxDiscs),         size("MAX_TRIANGLES", maxTriangles),
                                    size("MAX_TORI", maxTori)};
    all.insert(all.end(), extraDefines.begin(), extraDefines.end());
    return all;
}

bool StageInfo::available() const {
    std::error_code ec;
    return std::filesystem::is_directory(projectRoot() / "solution" / id, ec);
}

const std::vector<StageInfo>& allStages() {
    static const std::vector<StageInfo> stages = makeStages();
    return stages;
}

const StageInfo& findStage(const std::string& idOrNumber) {
    for (const StageInfo& s : allStages()) {
        bool numberMatches = !idOrNumber.empty() && idOrNumber.size() <= 2 &&
                             idOrNumber.find_first_not_of("0123456789") == std::string::npos &&
                             std::stoi(idOrNumber) == std::stoi(s.number());
        if (idOrNumber == s.id || numberMatches) {
            if (!s.available()) throw Error("stage " + s.id + " is not available yet (no solution/" + s.id + "/)");
            return s;
        }
    }
    throw Error("unknown stage '" + idOrNumber + "' (stages: " + stageList() + ")");
}

const StageInfo& latestAvailableStage() {
    const StageInfo* latest = nullptr;
    for (const StageInfo& s : allStages())
        if (s.available()) latest = &s;
    if (!latest) throw Error("no stage is available (solution/ is empty)");
    return *latest;
}

} // namespace raylab
