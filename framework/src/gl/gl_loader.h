#pragma once
// Loading OpenGL entry points. Students need not read this file.
//
// GLEW is used everywhere, but Debian's GLEW is built for GLX, so:
//  - under EGL and SDL, glewInit() may report "no GLX display" although it did
//    load every entry point through libglvnd; we accept that and check the
//    pointers instead of the return code;
//  - under OSMesa, GLEW's loader returns nothing usable, so the pointers the
//    framework uses are filled from OSMesaGetProcAddress.
#include <string>

namespace raylab {

using GetProcFn = void* (*)(const char* name);

// After a context is current: runs glewInit and checks the result.
void loadGlWithGlew();

// After a context is current: fills GLEW's function pointers from GETPROC.
void loadGlFrom(GetProcFn getProc);

// Throws Error unless the current context is OpenGL 3.3 or newer.
void requireGl33();

// "OpenGL 4.5 (Core Profile) Mesa 22.3.6 on llvmpipe (LLVM 15.0.6, 256 bits)"
std::string glDescription();

}  // namespace raylab
