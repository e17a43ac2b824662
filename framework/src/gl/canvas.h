#pragma once
// The only geometry the ray tracer rasterises: two triangles covering the
// screen. canvas.vert turns each corner into a primary ray direction.
#include "gl.h"

namespace raylab {

class Canvas {
public:
    Canvas();
    ~Canvas();
    Canvas(const Canvas&) = delete;
    Canvas& operator=(const Canvas&) = delete;

    void draw() const;  // binds attribute 0 = corner position in [-1, 1]^2

private:
    GLuint vao_ = 0;
    GLuint vbo_ = 0;
};

}  // namespace raylab
