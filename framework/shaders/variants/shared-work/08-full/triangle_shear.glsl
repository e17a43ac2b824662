// Part of the shared-work variant (the demo, and raylab bench's "shared"
// lever). Not part of any lab: students never see this file.
//
// solution/08-full/intersect_triangle.glsl split in two: the shear that
// makes the ray run along +z depends on the ray alone, so a search that
// tests several triangles against one ray (testOthers: the glass cube's 12)
// works it out once, not once a triangle. The arithmetic is the solution's,
// operation for operation, so every hit is the same to the bit.
struct TriangleShear {
    int kx, ky, kz;    // the axes: kz the direction's largest component
    float sx, sy, sz;  // the shear and the scale along kz
};

TriangleShear triangleShear(vec3 d)
{
    vec3 absD = abs(d);
    int kz = absD.x > absD.y ? (absD.x > absD.z ? 0 : 2) : (absD.y > absD.z ? 1 : 2);
    int kx = kz == 2 ? 0 : kz + 1;
    int ky = kx == 2 ? 0 : kx + 1;
    if (d[kz] < 0.0) { int swap = kx; kx = ky; ky = swap; }
    float sz = 1.0 / d[kz];
    return TriangleShear(kx, ky, kz, d[kx] * sz, d[ky] * sz, sz);
}

// intersectTriangle(ray, a, b, c) with the ray's shear given.
float intersectTriangleSheared(Ray ray, TriangleShear s, vec3 a, vec3 b, vec3 c)
{
    int kx = s.kx, ky = s.ky, kz = s.kz;
    float sx = s.sx, sy = s.sy, sz = s.sz;
    vec3 A = a - ray.origin;
    vec3 B = b - ray.origin;
    vec3 C = c - ray.origin;
    vec2 a2 = vec2(A[kx] - sx * A[kz], A[ky] - sy * A[kz]);
    vec2 b2 = vec2(B[kx] - sx * B[kz], B[ky] - sy * B[kz]);
    vec2 c2 = vec2(C[kx] - sx * C[kz], C[ky] - sy * C[kz]);
    float U = edgeFunction(c2, b2);
    float V = edgeFunction(a2, c2);
    float W = edgeFunction(b2, a2);
    if ((U < 0.0 || V < 0.0 || W < 0.0) && (U > 0.0 || V > 0.0 || W > 0.0)) return NO_HIT;
    float det = U + V + W;
    if (det == 0.0) return NO_HIT;
    vec3 normal = cross(b - a, c - a);
    if (dot(normal, normal) == 0.0) return NO_HIT;
    float T = U * (sz * A[kz]) + V * (sz * B[kz]) + W * (sz * C[kz]);
    float t = T / det;
    return t > T_MIN ? t : NO_HIT;
}
