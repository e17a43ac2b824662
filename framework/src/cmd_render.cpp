#include "commands.h"
#include "error.h"
#include "stage_renderer.h"

#include <cstdio>

namespace raylab {

namespace {
void checkOutputFile(const std::filesystem::path& out) {
    if (out.empty()) throw Error("--out FILE.png is required");
    if (out.extension() != ".png") throw Error("--out '" + out.string() + "': the file name must end in .png");
    std::error_code ec;
    std::filesystem::path dir = out.parent_path().empty() ? "." : out.parent_path();
    if (!std::filesystem::is_directory(dir, ec)) throw Error("--out '" + out.string() + "': folder " + dir.string() + " does not exist");
}
} // namespace

int cmdRender(const StageOptions& options, const std::string& outFile, Backend backend) {
    checkOutputFile(outFile);
    StageSetup setup = resolveStageOptions(options);
    auto context = createHeadlessContext(backend);
    StageRenderer renderer(*setup.stage, setup.sources, setup.scene, setup.size.width, setup.size.height);
    reportOpenTodos(renderer.openTodos());
    renderer.render(setup.camera, setup.time, setup.settings);
    writePngAtomic(renderer.read(), outFile);
    std::printf("raylab: wrote %s (%dx%d, stage %s, %s, %s backend)\n", outFile.c_str(), setup.size.width, setup.size.height,
                setup.stage->id.c_str(), setup.sources.label.c_str(), context->backendName().c_str());
    return 0;
}

} // namespace raylab
