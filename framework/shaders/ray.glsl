// Rays and hit records shared by every stage. (Students need not change this file.)

// A ray: origin + t * dir, with dir of unit length, so t is a distance.
struct Ray {
    vec3 origin;
    vec3 dir;
};

// The nearest hit found so far along a ray.
struct Hit {
    float t;  // distance along the ray; findClosest leaves T_FAR when nothing was hit
    int id;   // index of the object that was hit, -1 for none
};

// Defined by the framework at the top of every shader, with the same values
// as its C++ (framework/src/core/shader_constants.h):
//   NO_HIT     -1: returned by intersection functions when the ray misses
//   T_MIN      1e-4: hits closer than this are ignored, so a ray never hits
//              its own origin (stage 03: 0, so that a shadow ray not moved
//              off its surface shows the acne it causes)
//   T_FAR      1e30: a very large distance, "nothing hit yet"
//   MAX_DEPTH  8: rays per path (trace.glsl); MAX_RAYS = 2^MAX_DEPTH
