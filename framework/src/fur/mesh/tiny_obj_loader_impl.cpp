// tinyobjloader's implementation, compiled into the WebAssembly core only:
// natively it comes from Debian's libtinyobjloader (framework/CMakeLists.txt).
#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>
