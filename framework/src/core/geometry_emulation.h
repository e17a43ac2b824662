#pragma once
// A geometry shader run where there are none (WebGL 2): the student's
// geometry shader rewritten into a vertex shader, so that the page runs the
// fin.geom and strand.geom the student wrote.
//
// How it runs, in two draws:
//  1. Capture: the student's vertex shader runs once per corner of every
//     input primitive (the corners laid out one after the other, primitive by
//     primitive), and transform feedback keeps the outputs the geometry
//     shader reads: one record of `recordWords` 32-bit words per corner.
//  2. Emulation: the rewritten shader runs once per (input primitive, output
//     primitive slot, corner): drawArraysInstanced(mode, 0,
//     verticesPerPrimitive, primitives), one instance per input primitive,
//     reading that primitive's records through `attributes` uvec4 instanced
//     attributes `raylab_in0..`. Its body runs as written: EmitVertex()
//     counts the emissions and keeps the one this corner stands for,
//     EndPrimitive() ends a strip; slot i of a triangle strip is the
//     triangle of emissions i, i+1, i+2 (in the strip's winding), drawn only
//     where all three belong to one strip - the triangles (or lines, or
//     points) a geometry shader would have made, in its order. The others
//     collapse to a point outside the view. Once its emissions are kept, the
//     body stops at the next EmitVertex() where it can (a void function).
// The shader's output `raylab_kept` (flat int) is 1 on the vertices of the
// primitives drawn: transform feedback of it counts them (the fin count).
// Students need not read this file.
#include "shader_source.h"

#include <string>
#include <vector>

namespace raylab {

enum class EmulatedOutput { Points, Lines, Triangles };

struct EmulatedGeometry {
    ShaderSource vertex;                // the geometry shader as a vertex shader
    std::vector<std::string> captured;  // the vertex shader's outputs kept, in record order
    int corners = 0;                    // vertices per input primitive (4 for lines_adjacency)
    int recordWords = 0;                // 32-bit words per captured vertex
    int attributes = 0;                 // uvec4 attributes per input primitive
    EmulatedOutput output = EmulatedOutput::Triangles;
    int maxVertices = 0;      // the geometry shader's max_vertices
    int slots = 0;            // output primitives one input primitive can make
    int verticesPerSlot = 0;  // 1, 2 or 3
    int verticesPerPrimitive() const { return slots * verticesPerSlot; }
    std::string inputName;     // "lines_adjacency", for messages
    std::string json() const;  // everything but the source, for the page
};

// The output the emulated shader flags its drawn vertices with.
inline constexpr const char* kEmulationKeptOutput = "raylab_kept";

// Rewrites GEOMETRY (assembled, `#version 330 core` first) to read the
// outputs of VERTEX (assembled too). Lines keep their origin, so compile
// errors still name the student's file and line. Throws Error naming the
// file and line of what it cannot run (an input the vertex shader does not
// write, an interface block, gl_InvocationID, a matrix output ...).
EmulatedGeometry emulateGeometryShader(const ShaderSource& vertex, const ShaderSource& geometry);

// A fragment shader that writes nothing, for linking the capture program
// (VERSION: the first line, `#version 330 core` or `#version 300 es`).
ShaderSource captureFragmentShader(const std::string& version = kGlslVersionLine);

}  // namespace raylab
