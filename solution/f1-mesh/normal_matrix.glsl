//@open
//@ // The matrix that carries normals from object space to world space.
//@ //
//@ // TODO(f1.b): the normal matrix.
//@ // A normal is not a point: it must stay perpendicular to the
//@ // surface, under every model matrix this course uses (rotations, moves,
//@ // uniform and non-uniform scales, so a sphere squashed into an ellipsoid
//@ // too). Return the 3x3 matrix that does that for MODEL; its result need not
//@ // be unit length (guide, section 3 derives it).
//@ // Checked by: raylab check --stage f1 (function normalMatrix; view "squashed").
//@ #include "lab_todo.glsl"
//@
//@ mat3 normalMatrix(mat4 model)
//@ {
//@     labTodo();
//@     return mat3(1.0);
//@ }
//@guided
// The matrix that carries normals from object space to world space.
//
// A normal is not a point: it must stay perpendicular to the surface. The
// model matrix keeps it so under rotations and uniform scaling, but a
// non-uniform scale (a sphere squashed into an ellipsoid) tilts it off the
// surface. The inverse of the transpose of the model matrix's upper-left
// 3x3 keeps it perpendicular (guide, section 3).
#include "lab_todo.glsl"

mat3 normalMatrix(mat4 model)
{
    // TODO(f1.b): return the inverse transpose of the upper-left 3x3 of MODEL.
    // Checked by: raylab check --stage f1 (function normalMatrix, view "squashed").
    //@solution
    return transpose(inverse(mat3(model)));
    //@stub
    //@ labTodo();
    //@ return mat3(1.0);
    //@end
}
//@end-open
