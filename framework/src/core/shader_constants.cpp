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
    // A stage may set its own T_MIN with a define (stage.json "defines":
    // "RAYLAB_T_MIN 0.0"): stage 03 counts every hit in front of a ray, so
    // that a shadow ray started on its own surface shows the acne it causes.
    return floatConst("NO_HIT", kNoHit) +
           "#ifdef RAYLAB_T_MIN\nconst float T_MIN = RAYLAB_T_MIN;\n#else\n" +
           floatConst("T_MIN", kTMin) + "#endif\n" + floatConst("T_FAR", kTFar) +
           intConst("MAX_DEPTH", kMaxDepth) + intConst("MAX_RAYS", kMaxRays) +
           intConst("KIND_SPHERE", kSphere) + intConst("KIND_PLANE", kPlane) +
           intConst("KIND_DISC", kDisc) + intConst("KIND_TRIANGLE", kTriangle) +
           intConst("KIND_TORUS", kTorus) + intConst("KIND_MESH", kMesh) +
           intConst("OBJECT_KIND_STRIDE", kObjectKindStride);
}

}  // namespace raylab::shader
