// PNG files through SDL2_image (image.h). Kept apart from the pixel
// arithmetic in image.cpp: the WebAssembly core (web/README.md) has no SDL2
// and leaves this file out; the page decodes images in the browser.
#include "image.h"

#include "error.h"
#include "paths.h"

#include <SDL.h>
#include <SDL_image.h>

#include <cstring>
#include <memory>
#include <string>
#include <unistd.h>

namespace raylab {

namespace {
struct SurfaceDeleter {
    void operator()(SDL_Surface* s) const { SDL_FreeSurface(s); }
};
using SurfacePtr = std::unique_ptr<SDL_Surface, SurfaceDeleter>;
}  // namespace

Image loadPng(const std::filesystem::path& file) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec))
        throw Error("cannot read image " + displayPath(file) + ": no such file");
    SurfacePtr loaded(IMG_Load(file.c_str()));
    if (!loaded) throw Error("cannot read image " + displayPath(file) + ": " + IMG_GetError());
    SurfacePtr rgba(SDL_ConvertSurfaceFormat(loaded.get(), SDL_PIXELFORMAT_RGBA32, 0));
    if (!rgba) throw Error("cannot convert image " + displayPath(file) + ": " + SDL_GetError());
    Image image(rgba->w, rgba->h);
    for (int y = 0; y < rgba->h; ++y)
        std::memcpy(image.pixel(0, y),
                    static_cast<const std::uint8_t*>(rgba->pixels) + y * rgba->pitch,
                    std::size_t(rgba->w) * 4);
    return image;
}

void writePngAtomic(const Image& image, const std::filesystem::path& file) {
    std::error_code ec;
    std::filesystem::path dir = file.parent_path().empty() ? "." : file.parent_path();
    if (!std::filesystem::is_directory(dir, ec))
        throw Error("cannot write " + file.string() + ": folder " + dir.string() +
                    " does not exist");
    SurfacePtr surface(SDL_CreateRGBSurfaceWithFormatFrom(
        const_cast<std::uint8_t*>(image.rgba.data()), image.width, image.height, 32,
        image.width * 4, SDL_PIXELFORMAT_RGBA32));
    if (!surface) throw Error(std::string("cannot create image surface: ") + SDL_GetError());
    std::filesystem::path tmp = file;
    tmp += ".tmp-" + std::to_string(::getpid());
    if (IMG_SavePNG(surface.get(), tmp.c_str()) != 0) {
        std::filesystem::remove(tmp, ec);
        throw Error("cannot write " + file.string() + ": " + IMG_GetError());
    }
    std::filesystem::rename(tmp, file, ec);
    if (ec) {
        std::filesystem::remove(tmp, ec);
        throw Error("cannot write " + file.string() + ": " + ec.message());
    }
}

}  // namespace raylab
