// Rays and hit records shared by every stage. (Students need not change this file.)

// A ray: origin + t * dir, with dir of unit length, so t is a distance.
struct Ray {
    vec3 origin;
    vec3 dir;
};

// The nearest hit found so far along a ray.
struct Hit {
    float t;  // distance along the ray; NO_HIT when nothing was hit
    int id;   // index of the object that was hit, -1 for none
};

// Returned by intersection functions when the ray misses.
const float NO_HIT = -1.0;

// Hits closer than this are ignored: a ray never hits its own origin.
const float T_MIN = 1e-4;

// A very large distance: "nothing hit yet".
const float T_FAR = 1e30;
