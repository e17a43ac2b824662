// tinyobjloader's implementation, compiled into the WebAssembly core and the
// fuzzers (tests/fuzz: so that they see its branches too); the native build
// links Debian's libtinyobjloader instead (framework/CMakeLists.txt).
#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>
