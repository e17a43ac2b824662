// Is the edge B-C on the silhouette, seen from EYE?
//
// The geometry shader gets the edge with its two triangles: A-B-C on one
// side and B-C-D on the other (A and D are the corners across the edge),
// both wound the same way (counter-clockwise seen from outside).
//
// Eli's approach: classify each triangle on its own as +1 (faces the eye),
// -1 (faces away) or 0 (eye in its plane, or a zero-area triangle), then ask
// for opposite classes. A boundary edge (D == A) always gets opposite classes.
#include "lab_todo.glsl"

/* Which side of the plane through `corner` with normal firstEdge x secondEdge
 * the eye is on: +1 outside, -1 inside, 0 in the plane / no plane at all. */
float eliSideOfEye(vec3 eye, vec3 corner, vec3 firstEdge, vec3 secondEdge)
{
    vec3 outward = cross(firstEdge, secondEdge);
    return sign(dot(eye - corner, outward));
}

bool isSilhouette(vec3 eye, vec3 a, vec3 b, vec3 c, vec3 d)
{
    vec3 edgeBC = c - b;
    float frontSide = eliSideOfEye(eye, b, b - a, edgeBC);   /* triangle A, B, C */
    float backSide  = eliSideOfEye(eye, b, d - b, edgeBC);   /* triangle B, D, C */
    return frontSide * backSide < 0.0;
}
