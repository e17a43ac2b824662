// tinyobjloader's implementation, compiled with the fuzzers' instrumentation
// (the header Debian's libtinyobjloader-dev ships holds it).
#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>
