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
    return uModel * vec4(objectPoint, 1.0);
}

vec4 toClip(vec4 world)
{
    return uProjection * uView * world;
}
