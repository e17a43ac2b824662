// Where a point of the mesh goes: into world space (where the lighting is
// worked out) and from there onto the screen (clip space). Later stages move
// points in world space between the two (the shells, the fins, the strands),
// so they are two functions.
//
// uModel takes a point from object space to world space, uView from world
// space to the camera's, uProjection from the camera's to clip space
// (guide, section 2). A point is vec4(p, 1.0).
#include "lab_todo.glsl"

vec4 toWorld(vec3 objectPoint)
{
    // TODO(f1.a): the point in world space.
    // Checked by: raylab check --stage f1 (function toWorld; all views).
    labTodo();
    return vec4(objectPoint, 1.0);
}

vec4 toClip(vec4 world)
{
    // TODO(f1.a): the world-space point WORLD in clip space.
    // Checked by: raylab check --stage f1 (function toClip; all views).
    labTodo();
    return vec4(0.5 * world.xy, 0.0, 1.0);
}
