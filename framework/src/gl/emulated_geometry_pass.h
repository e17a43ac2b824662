#pragma once
// A vertex + geometry + fragment program drawn without a geometry shader,
// as the page draws it (WebGL 2 has none): the geometry shader rewritten by
// emulateGeometryShader (geometry_emulation.h), the vertex shader's outputs
// captured by transform feedback. Native draws fins and strands with real
// geometry shaders; this runs the page's way on desktop GL 3.3, so that
// native tests compare the two. Students need not read this file.
#include "geometry_emulation.h"
#include "shader_program.h"

#include <memory>
#include <utility>
#include <vector>

namespace raylab {

class EmulatedGeometryPass {
public:
    // Throws ShaderError (compile, link) or Error (what the emulation cannot run).
    EmulatedGeometryPass(const ShaderSource& vertex, const ShaderSource& geometry,
                         const ShaderSource& fragment);
    ~EmulatedGeometryPass();
    EmulatedGeometryPass(const EmulatedGeometryPass&) = delete;
    EmulatedGeometryPass& operator=(const EmulatedGeometryPass&) = delete;

    // The capture and the expand read the stage's uniforms, the draw those
    // of its outputs' fragment shader: the caller sets them on each.
    const ShaderProgram& capture() const { return *capture_; }
    const ShaderProgram& expand() const { return *expand_; }
    const ShaderProgram& draw() const { return *draw_; }
    const EmulatedGeometry& layout() const { return layout_; }

    // The input primitives' corners, one after the other: FLOATS per corner
    // interleaved as ATTRIBUTES says ({location, size}), for the vertex shader.
    void setCorners(const std::vector<float>& floats,
                    const std::vector<std::pair<int, int>>& attributes);

    // Runs the vertex shader on the corners, the geometry shader on their
    // primitives, then draws the primitives it made. With COUNT, draws
    // nothing and returns how many it made (transform feedback of
    // raylab_kept). Leaves texture unit kEmissionTextureUnit bound.
    long run(bool count = false);

private:
    EmulatedGeometry layout_;
    std::unique_ptr<ShaderProgram> capture_, expand_, draw_;
    GLuint cornerVao_ = 0, corners_ = 0, recordVao_ = 0, records_ = 0, emptyVao_ = 0;
    GLuint emissions_ = 0, emissionTexture_ = 0, kept_ = 0;
    long cornerCount_ = 0;
    EmissionTextureSize textureSize_;
};

}  // namespace raylab
