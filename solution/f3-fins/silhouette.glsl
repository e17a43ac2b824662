//@open
//@ // Is the edge B-C on the silhouette, seen from EYE?
//@ //
//@ // The geometry shader gets the edge with its two triangles: A-B-C on one
//@ // side and B-C-D on the other (A and D are the corners across the edge),
//@ // both wound the same way (counter-clockwise seen from outside).
//@ // TODO(f3.a): whether the edge is on the silhouette.
//@ // True when exactly one of the two triangles faces the eye
//@ // (guide, section 4). A degenerate triangle (zero area) faces neither way:
//@ // no silhouette.
//@ // Checked by: raylab check --stage f3 (function isSilhouette, the fin
//@ // count, every view with fins).
//@ #include "lab_todo.glsl"
//@
//@ bool isSilhouette(vec3 eye, vec3 a, vec3 b, vec3 c, vec3 d)
//@ {
//@     labTodo();
//@     return true;  // until then: a fin on every edge
//@ }
//@guided
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
    //@solution
    vec3 pb = b - eye;
    vec3 bc = c - b;
    vec3 nAbc = cross(b - a, bc);
    vec3 nBcd = cross(d - b, bc);
    return dot(pb, nAbc) * dot(pb, nBcd) < 0.0;
    //@stub
    //@ labTodo();
    //@ return true;  // until then: a fin on every edge
    //@end
}
//@end-open
