// Is the edge B-C on the silhouette, seen from EYE?
//
// The geometry shader gets the edge with its two triangles: A-B-C on one
// side and B-C-D on the other (A and D are the corners across the edge),
// both wound the same way (counter-clockwise seen from outside).
// dana: silhouette = the two faces disagree about the eye. Both normals come
// from the CCW winding, un-normalised (only signs matter); a degenerate face
// gives 0 and so no fin.
#include "lab_todo.glsl"

bool isSilhouette(vec3 eye, vec3 a, vec3 b, vec3 c, vec3 d)
{
    vec3 pb = b - eye;
    vec3 nAbc = cross(b - a, c - b);
    vec3 nBcd = cross(d - b, c - b);
    return dot(pb, nAbc) * dot(pb, nBcd) < 0.0;   // opposite signs
}
