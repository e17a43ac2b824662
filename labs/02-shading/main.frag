// The main program from stage 02 (shading) on, until a later stage replaces
// it: the nearest hit is found as in stage 01; instead of a flat colour the
// pixel gets the Blinn-Phong colour of that point, lit by the scene's point
// lights.
#include "ray.glsl"
#include "scene_spheres.glsl"
#include "scene_materials.glsl"
#include "scene_lights.glsl"
#include "lab_todo.glsl"
#include "intersect_sphere.glsl"
#include "find_closest.glsl"
#include "blinn_phong.glsl"

in vec3 vsRay;
uniform vec3 uEye;
layout(location = 0) out vec4 fragColor;

void main()
{
    Ray ray = Ray(uEye, normalize(vsRay));
    Hit hit;
    vec3 color = uBackground;
    if (findClosest(ray, hit)) {
        vec3 point = ray.origin + hit.t * ray.dir;
        vec3 normal = normalize(point - uSpheres[hit.id].xyz);
        // Seen from inside a sphere, light the side we are looking at.
        if (dot(normal, ray.dir) > 0.0) normal = -normal;
        color = blinnPhong(point, normal, -ray.dir, materialOfSphere(hit.id));
    }
    fragColor = vec4(labOverlay(color), 1.0);
}
