// Is the edge B-C on the silhouette, seen from EYE?
//
// The geometry shader gets the edge with its two triangles: A-B-C on one
// side and B-C-D on the other (A and D are the corners across the edge).
// The edge is on the silhouette when one triangle faces the eye and the
// other faces away. With PB = B - EYE and the normals
//     N_abc = (B - A) x (C - B)    and    N_bcd = (D - B) x (C - B),
// a triangle faces the eye when PB . N < 0, so the two differ exactly when
// the product (PB . N_abc) (PB . N_bcd) is negative (guide, section 4).
#include "lab_todo.glsl"

bool isSilhouette(vec3 eye, vec3 a, vec3 b, vec3 c, vec3 d)
{
    // TODO(f3.a): compute both dot products and test the sign of their
    // product as above. A degenerate triangle (zero normal) is no silhouette.
    // Checked by: raylab check --stage f3 (function isSilhouette, the fin
    // count, every view with fins).
    labTodo();
    return true;  // until then: a fin on every edge
}
