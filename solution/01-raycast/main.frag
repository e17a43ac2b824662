// Stage 01 - ray casting. One primary ray per pixel; the pixel takes the flat
// colour of the nearest sphere the ray hits, or the background colour.
#include "ray.glsl"
#include "scene_spheres.glsl"
#include "lab_todo.glsl"
#include "intersect_sphere.glsl"
#include "find_closest.glsl"

in vec3 vsRay;           // from canvas.vert: eye -> this pixel on the canvas
uniform vec3 uEye;
layout(location = 0) out vec4 fragColor;

void main()
{
    Ray ray = Ray(uEye, normalize(vsRay));
    Hit hit;
    vec3 color = findClosest(ray, hit) ? uSphereColors[hit.id] : uBackground;
    fragColor = vec4(labOverlay(color), 1.0);
}
