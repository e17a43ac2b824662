#pragma once
// A geometry shader run where there are none (WebGL 2): the student's
// geometry shader rewritten into a vertex shader, so that the page runs the
// fin.geom and strand.geom the student wrote.
//
// How it runs, in three draws and a copy:
//  1. Capture: the student's vertex shader runs once per corner of every
//     input primitive (the corners laid out one after the other, primitive by
//     primitive), and transform feedback keeps the outputs the geometry
//     shader reads: one record of `recordWords` 32-bit words per corner.
//  2. Expand: the rewritten geometry shader (`expand`) runs `runs` times per
//     input primitive: drawArraysInstanced(POINTS, 0, primitives, runs), a
//     vertex per input primitive (its records read through `attributes`
//     uvec4 attributes `raylab_in0..`) and an instance per run. Its body
//     runs as written; run r keeps emissions r*K .. r*K+K-1 (K =
//     `emissionsPerRun`) as `emissionTexels` uvec4 outputs each, which
//     transform feedback writes one after the other, run by run. An
//     emission's first word says its strip (EndPrimitive() ends one) and its
//     place in it; 0 where the body made none. Once a run's emissions are
//     kept, the body stops at the next EmitVertex() where it can (a void
//     function). K is as many as transform feedback's 64 components allow
//     (WebGL 2's least), so a body of E emissions runs about E / K times,
//     not once per emission; and the vertices a driver runs side by side
//     are the same run of neighbouring primitives, which stop at about the
//     same emission.
//  3. The emissions are copied into a 2D array texture of RGBA32UI texels
//     (`kEmissionTextureWidth` wide, `kEmissionLayerRows` rows a layer), the
//     transform feedback buffer bound as the pixel unpack buffer.
//  4. Draw: `draw` runs once per (input primitive, output primitive slot,
//     corner): drawArrays(mode, 0, primitives * verticesPerPrimitive()).
//     Slot i of a triangle strip is the triangle of emissions i, i+1, i+2 (in
//     the strip's winding), drawn only where all three belong to one strip -
//     the triangles (or lines, or points) a geometry shader would have made,
//     in its order. The others collapse to a point outside the view. It
//     writes the geometry shader's outputs, declared as the student did.
// The draw's output `raylab_kept` (flat int) is 1 on the vertices of the
// primitives drawn: transform feedback of it counts them (the fin count).
// Students need not read this file.
#include "shader_source.h"

#include <string>
#include <vector>

namespace raylab {

enum class EmulatedOutput { Points, Lines, Triangles };

// The emissions' texture: texels per row, rows per layer.
inline constexpr int kEmissionTextureWidth = 1024;
inline constexpr int kEmissionLayerRows = 1024;
// The texture unit the draw reads the emissions from (the stages' own
// textures take the first units).
inline constexpr int kEmissionTextureUnit = 15;

struct EmulatedGeometry {
    ShaderSource expand;                // the geometry shader as a vertex shader: its emissions out
    ShaderSource draw;                  // the primitives drawn from the emissions
    std::vector<std::string> captured;  // the vertex shader's outputs kept, in record order
    std::vector<std::string> emitted;   // expand's outputs kept, in order
    int corners = 0;                    // vertices per input primitive (4 for lines_adjacency)
    int recordWords = 0;                // 32-bit words per captured vertex
    int attributes = 0;                 // uvec4 attributes per input primitive
    EmulatedOutput output = EmulatedOutput::Triangles;
    int maxVertices = 0;      // the geometry shader's max_vertices
    int slots = 0;            // output primitives one input primitive can make
    int verticesPerSlot = 0;  // 1, 2 or 3
    int emissionTexels = 0;   // RGBA32UI texels per emission
    int emissionsPerRun = 0;  // emissions one run of the body keeps
    int runs = 0;             // runs of the body per input primitive
    int verticesPerPrimitive() const { return slots * verticesPerSlot; }
    int emissionsPerPrimitive() const { return runs * emissionsPerRun; }
    std::string inputName;     // "lines_adjacency", for messages
    std::string json() const;  // everything but the sources, for the page
};

// The output the emulated shader flags its drawn vertices with.
inline constexpr const char* kEmulationKeptOutput = "raylab_kept";
// The draw's sampler of the emissions, and its uniform int: how many input
// primitives there are.
inline constexpr const char* kEmissionSampler = "raylab_emissions";
inline constexpr const char* kEmulationPrimitivesUniform = "raylab_primitives";

// The emissions' texture for PRIMITIVES input primitives: its rows and
// layers, and the bytes of transform feedback buffer it is copied from.
struct EmissionTextureSize {
    int rows = 0, layers = 0;
    long long bytes() const { return 16LL * kEmissionTextureWidth * rows * layers; }
};
EmissionTextureSize emissionTextureSize(const EmulatedGeometry& e, long primitives);

// Rewrites GEOMETRY (assembled, `#version 330 core` first) to read the
// outputs of VERTEX (assembled too). Lines keep their origin, so compile
// errors still name the student's file and line. Throws Error naming the
// file and line of what it cannot run (an input the vertex shader does not
// write, an interface block, gl_InvocationID, a matrix output ...).
EmulatedGeometry emulateGeometryShader(const ShaderSource& vertex, const ShaderSource& geometry);

// A fragment shader that writes nothing, for linking the capture and
// expand programs (VERSION: the first line, `#version 330 core` or
// `#version 300 es`).
ShaderSource captureFragmentShader(const std::string& version = kGlslVersionLine);

}  // namespace raylab
