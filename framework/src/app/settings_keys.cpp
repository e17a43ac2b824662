#include "settings_keys.h"

#include "mesh_shapes.h"
#include "text_format.h"

#include <algorithm>
#include <cmath>

namespace raylab {

namespace {

constexpr float kFurLengthStep = 1.25f;  // - and = multiply or divide the length by this
constexpr float kMinFurLength = 0.25f, kMaxFurLength = 4.0f;

std::optional<std::string> rayTracerKey(RenderSettings& s, SDL_Keycode key) {
    switch (key) {
    case SDLK_1: s.shadows = !s.shadows; return std::string("shadows ") + onOff(s.shadows);
    case SDLK_g: s.glow = !s.glow; return std::string("glow ") + onOff(s.glow);
    case SDLK_n:
        s.normalMaps = !s.normalMaps;
        return std::string("normal maps ") + onOff(s.normalMaps);
    case SDLK_RIGHT:
    case SDLK_LEFT:
        s.maxDepth =
            std::clamp(s.maxDepth + (key == SDLK_RIGHT ? 1 : -1), 1, RenderSettings::kMaxDepth);
        return "max depth " + std::to_string(s.maxDepth);
    case SDLK_UP:
    case SDLK_DOWN:
        s.colorMode = (s.colorMode + (key == SDLK_UP ? 1 : kColorModeCount - 1)) % kColorModeCount;
        return std::string("colour mode ") + kColorModes[s.colorMode];
    default: return std::nullopt;
    }
}

std::string meshName(int furMesh) {
    const std::vector<std::string>& shapes = shapeNames();
    return furMesh > 0 && furMesh <= int(shapes.size()) ? shapes[std::size_t(furMesh - 1)]
                                                        : "the scene's";
}

std::string lengthFactor(float f) { return "x" + significant(double(f), 3); }

std::optional<std::string> furKey(RenderSettings& s, SDL_Keycode key) {
    switch (key) {
    case SDLK_LEFTBRACKET:
    case SDLK_RIGHTBRACKET:
        s.shells = std::clamp(s.shells + (key == SDLK_RIGHTBRACKET ? 1 : -1), 1,
                              RenderSettings::kMaxShells);
        return "shells " + std::to_string(s.shells);
    case SDLK_MINUS:
    case SDLK_EQUALS:
        s.furLength = std::clamp(key == SDLK_EQUALS ? s.furLength * kFurLengthStep
                                                    : s.furLength / kFurLengthStep,
                                 kMinFurLength, kMaxFurLength);
        return "fur length " + lengthFactor(s.furLength);
    case SDLK_f: s.fins = !s.fins; return std::string("fins ") + onOff(s.fins);
    case SDLK_t:
        s.furTechnique = (s.furTechnique + 1) % kFurTechniqueCount;
        return std::string("technique ") + kFurTechniques[s.furTechnique];
    case SDLK_m:
        s.furMesh = (s.furMesh + 1) % (int(shapeNames().size()) + 1);
        return "mesh " + meshName(s.furMesh);
    default: return std::nullopt;
    }
}

}  // namespace

const char* onOff(bool on) { return on ? "on" : "off"; }

std::optional<std::string> applySettingsKey(RenderSettings& s, SDL_Keycode key,
                                            const std::string& track) {
    return track == "fur" ? furKey(s, key) : rayTracerKey(s, key);
}

std::vector<std::pair<std::string, std::string>> settingsRows(const RenderSettings& s,
                                                              const std::string& track) {
    if (track == "fur")
        return {{"[ [ ] ] shells", std::to_string(s.shells)},
                {"[-/=] fur length", lengthFactor(s.furLength)},
                {"[F] fins", onOff(s.fins)},
                {"[T] technique", kFurTechniques[s.furTechnique]},
                {"[M] mesh", meshName(s.furMesh)}};
    return {{"[1] shadows", onOff(s.shadows)},
            {"[G] glow", onOff(s.glow)},
            {"[N] normal maps", onOff(s.normalMaps)},
            {"[Left/Right] max depth", std::to_string(s.maxDepth)},
            {"[Up/Down] colour mode", kColorModes[s.colorMode]}};
}

}  // namespace raylab
