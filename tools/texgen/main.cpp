// raylab-texgen: writes the procedural textures the ray tracer's later stages
// use (planets, sky box, floor patterns) and the fur track's (coat colour,
// fur pattern, fin strands). Nothing is downloaded: every pixel
// comes from the generators in this folder, deterministically, so the
// committed files in assets/textures/ can be checked by regenerating them.
//
//   raylab-texgen OUTDIR     e.g. build/raylab-texgen assets/textures
//   raylab-texgen --help
#include "error.h"
#include "texture_set.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <string>
#include <system_error>

using namespace raylab;
namespace fs = std::filesystem;

int main(int argc, char** argv) {
    CLI::App app{"Writes the procedural textures of assets/textures/ (planets, sky, tiles, "
                 "normal maps, fur) into OUTDIR."};
    std::string out;
    app.add_option("OUTDIR", out, "the folder to write (made when missing)")
        ->required()
        ->check([](const std::string& v) {
            return !v.empty() && v[0] == '-' ? "OUTDIR may not start with '-' (an option?)" : "";
        });
    CLI11_PARSE(app, argc, argv);
    const fs::path outDir = out;
    try {
        // Checked before the (slower) generation, so a bad OUTDIR fails fast.
        std::error_code ec;
        fs::create_directories(outDir, ec);
        if (ec || !fs::is_directory(outDir))
            throw Error("cannot write to " + outDir.string() + ": " +
                        (ec ? ec.message() : "not a folder"));
        for (const texgen::NamedImage& t : texgen::generateAllTextures()) {
            const fs::path file = outDir / t.fileName;
            writePngAtomic(t.image, file);
            std::printf("texgen: wrote %s (%dx%d)\n", file.c_str(), t.image.width, t.image.height);
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "raylab-texgen: error: %s\n", e.what());
        return 1;
    }
    return 0;
}
