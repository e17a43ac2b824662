// Is the edge B-C on the silhouette, seen from EYE?
//
// The geometry shader gets the edge with its two triangles: A-B-C on one
// side and B-C-D on the other (A and D are the corners across the edge),
// both wound the same way (counter-clockwise seen from outside).
// TODO(f3.a): whether the edge is on the silhouette.
// True when exactly one of the two triangles faces the eye
// (guide, section 4). A degenerate triangle (zero area) faces neither way:
// no silhouette.
// Checked by: raylab check --stage f3 (function isSilhouette, the fin
// count, every view with fins).

bool isSilhouette(vec3 eye, vec3 a, vec3 b, vec3 c, vec3 d)
{
    vec3 pb = b - eye;
    vec3 nAbc = cross(b - a, c - b);
    vec3 nBcd = cross(d - b, c - b);
    return dot(pb, nAbc) * dot(pb, nBcd) < 0.0;
}
