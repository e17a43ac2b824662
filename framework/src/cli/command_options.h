#pragma once
// Options that several commands share, defined once.
#include "gl_context.h"
#include "stage_setup.h"

#include <CLI/CLI.hpp>

namespace raylab {

// --stage, --lab [DIR], --solution, --scene, --size and, WITHCAMERA, the
// camera, time and switches. Returns the --lab option: whether it was given
// is known only after parsing (its count()).
CLI::Option* addStageOptions(CLI::App& cmd, StageOptions& o, bool withCamera);
// --scene-scale and --scene-offset (part of withCamera; check adds them too).
void addSceneTransformOptions(CLI::App& cmd, StageOptions& o);

// --backend auto|egl|osmesa. The name is checked when the command runs,
// like every other value (one line, exit 2).
class BackendOption {
public:
    explicit BackendOption(CLI::App& cmd);
    Backend resolve() const { return parseBackend(name_); }

private:
    std::string name_ = "auto";
};

}  // namespace raylab
