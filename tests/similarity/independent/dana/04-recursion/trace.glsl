// The ray tracer: every ray a pixel's primary ray leads to, by reflection
// and refraction, up to a depth limit. GLSL has no recursive calls.
#include "ray_offset.glsl"

uniform int uMaxDepth;  // rays per path, 1..MAX_DEPTH (arrow keys; MAX_DEPTH = 8 is defined by the framework)

// dana's tracer. One "current" ray is followed; where glass splits a ray in
// two, the refracted one waits on the stack and the reflected one is followed
// at once. Each waiting ray keeps its own weight (product of the shares along
// its path) and depth, so MAX_DEPTH slots are enough (guide, sec. 1).

struct Job {
    Ray ray;
    vec3 weight;
    int depth;
};

vec3 trace(Ray primary)
{
    Job stack[MAX_DEPTH];
    int top = 0;

    Job cur = Job(primary, vec3(1.0), 1);
    bool live = true;          // false: cur is done, take the next one off the stack
    vec3 sum = vec3(0.0);

    for (int iter = 0; iter < MAX_RAYS; ++iter) {
        if (!live) {
            if (top == 0) break;
            cur = stack[--top];
        }
        live = false;

        Hit hit;
        if (!findClosest(cur.ray, hit)) {
            sum += cur.weight * skyColor(cur.ray.dir);
            continue;
        }

        Surface s = surfaceAt(cur.ray, hit);
        Material m = s.material;
        bool entering = dot(cur.ray.dir, s.normal) < 0.0;
        vec3 N = entering ? s.normal : -s.normal;     // faces the incoming ray

        sum += cur.weight * blinnPhong(s.point, N, -cur.ray.dir, m);

        if (m.type == MAT_PLASTIC || cur.depth >= uMaxDepth) continue;

        int d = cur.depth + 1;
        Ray refl = Ray(offsetRayOrigin(s.point, N), reflect(cur.ray.dir, N));

        if (m.type == MAT_MIRROR) {
            cur = Job(refl, cur.weight * m.specular, d);
            live = true;
        } else if (m.type == MAT_METAL) {
            float ci = clamp(-dot(cur.ray.dir, N), 0.0, 1.0);
            cur = Job(refl, cur.weight * fresnelConductor(ci, m.n, m.k), d);
            live = true;
        } else if (m.type == MAT_GLASS) {
            vec4 tf = refractGlass(cur.ray.dir, N, entering, m.ior);
            // refracted part waits (none under total internal reflection)
            if (dot(tf.xyz, tf.xyz) > 0.0 && top < MAX_DEPTH) {
                Ray through = Ray(offsetRayOrigin(s.point, -N), tf.xyz);
                stack[top++] = Job(through, cur.weight * (1.0 - tf.w), d);
            }
            cur = Job(refl, cur.weight * tf.w, d);
            live = true;
        }
    }
    return sum;
}
