#pragma once
// The keys that switch how frames are drawn (1, G, N, arrows), separate from
// the window so that tests can check them without one.
#include "stage_renderer.h"

#include <SDL.h>

#include <optional>
#include <string>

namespace raylab {

// "on" or "off", for echoes and the overlay.
const char* onOff(bool on);

// Applies KEY to SETTINGS. Returns the line to echo on the terminal
// ("glow off", "colour mode BRB"), or nothing when KEY is not a settings key.
std::optional<std::string> applySettingsKey(RenderSettings& settings, SDL_Keycode key);

}  // namespace raylab
