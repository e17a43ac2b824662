#include "shader_constants.h"

#include "text_format.h"

namespace raylab::shader {

namespace {

// Enough digits that the GLSL float is the nearest one to the C++ double.
std::string floatConst(const char* name, double value) {
    // Always a float literal ("-1.0", not "-1"): GLSL ES 3.00 (WebGL 2) has
    // no implicit int-to-float conversion, even in a constant.
    std::string literal = significant(value, 9);
    if (literal.find_first_of(".eEn") == std::string::npos) literal += ".0";
    return "const float " + std::string(name) + " = " + literal + ";\n";
}

std::string intConst(const char* name, int value) {
    return "const int " + std::string(name) + " = " + std::to_string(value) + ";\n";
}

}  // namespace

std::string constantsGlsl() {
    return floatConst("NO_HIT", kNoHit) + floatConst("T_MIN", kTMin) + floatConst("T_FAR", kTFar) +
           intConst("MAX_DEPTH", kMaxDepth) + intConst("MAX_RAYS", kMaxRays) +
           intConst("KIND_SPHERE", kSphere) + intConst("KIND_PLANE", kPlane) +
           intConst("KIND_DISC", kDisc) + intConst("KIND_TRIANGLE", kTriangle) +
           intConst("KIND_TORUS", kTorus) + intConst("KIND_MESH", kMesh) +
           intConst("OBJECT_KIND_STRIDE", kObjectKindStride);
}

}  // namespace raylab::shader
