#pragma once
// The keys that switch how frames are drawn, separate from the window so
// that tests can check them without one. Each track has its own: the ray
// tracer 1, G, N and the arrows; the fur track [ ], - =, F, T and M.
#include "render_settings.h"

#include <SDL.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace raylab {

// "on" or "off", for echoes and the overlay.
const char* onOff(bool on);

// Applies KEY to SETTINGS for a stage of TRACK. Returns the line to echo on
// the terminal ("glow off", "shells 31"), or nothing when KEY is not one of
// the track's settings keys.
std::optional<std::string> applySettingsKey(RenderSettings& settings, SDL_Keycode key,
                                            const std::string& track = "raytrace");

// The overlay's rows for TRACK's settings: ("[G] glow", "on"), ...
std::vector<std::pair<std::string, std::string>> settingsRows(const RenderSettings& settings,
                                                              const std::string& track);

}  // namespace raylab
