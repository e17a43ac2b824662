#include "settings_keys.h"

#include <algorithm>

namespace raylab {

const char* onOff(bool on) { return on ? "on" : "off"; }

std::optional<std::string> applySettingsKey(RenderSettings& s, SDL_Keycode key) {
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

}  // namespace raylab
