#include "track_renderer.h"

#include "error.h"

namespace raylab {

CountResult TrackRenderer::countCheck(const std::string& name, const Camera&, float,
                                      const RenderSettings&) {
    throw Error("this track has no count check '" + name + "'");
}

}  // namespace raylab
