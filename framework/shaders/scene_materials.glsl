// The scene's material table, uploaded by the framework from the scene file:
// one entry per material, each object names its entry. (Students need not
// change this file.)
const int MAT_PLASTIC = 0;  // Blinn-Phong only
const int MAT_MIRROR = 1;   // also reflects, with the specular colour as reflectance
const int MAT_GLASS = 2;    // also reflects and refracts (Fresnel, index of refraction `ior`)
const int MAT_METAL = 3;    // also reflects, Fresnel from the complex index n + ik

struct Material {
    vec3 ambient;     // seen even where no light arrives
    vec3 diffuse;     // matte reflection, the same in every direction
    vec3 specular;    // shiny highlight colour
    float shininess;  // highlight exponent: larger = smaller, sharper highlight
    int type;         // MAT_PLASTIC, MAT_MIRROR, MAT_GLASS or MAT_METAL
    float ior;        // glass: index of refraction
    vec3 n;           // metal: real part of the index of refraction, per channel
    vec3 k;           // metal: extinction coefficient, per channel
    int texture;      // layer of uTextures multiplying ambient and diffuse, -1: none (stage 06)
    int normalMap;    // layer of uTextures, -1: none (stage 07)
};

#ifndef SCENE_BAKED  // else constants (framework/src/raytrace/scene/scene_baking.cpp)
uniform vec3 uMatAmbient[MAX_MATERIALS];
uniform vec3 uMatDiffuse[MAX_MATERIALS];
uniform vec3 uMatSpecular[MAX_MATERIALS];
uniform float uMatShininess[MAX_MATERIALS];
uniform int uMatType[MAX_MATERIALS];
uniform float uMatIor[MAX_MATERIALS];
uniform vec3 uMatN[MAX_MATERIALS];
uniform vec3 uMatK[MAX_MATERIALS];
uniform int uMatTexture[MAX_MATERIALS];
uniform int uMatNormalMap[MAX_MATERIALS];
#endif
#include "scene_spheres.glsl"  // MAX_SPHERES, SPHERE_BLOCK (included once)
#if !defined(SCENE_BAKED) || defined(RAYLAB_SPHERE_STORAGE)  // else constants (scene_baking.cpp)
layout(std140) SPHERE_BLOCK SphereMaterials {  // a block, as the spheres (scene_spheres.glsl)
    int uSphereMaterial[MAX_SPHERES];          // material index of each sphere
};
#endif

Material materialAt(int m)
{
    return Material(uMatAmbient[m], uMatDiffuse[m], uMatSpecular[m], uMatShininess[m], uMatType[m], uMatIor[m], uMatN[m],
                    uMatK[m], uMatTexture[m], uMatNormalMap[m]);
}

Material materialOfSphere(int sphere)
{
    return materialAt(uSphereMaterial[sphere]);
}
