// The scene's material table, uploaded by the framework from the scene file:
// one entry per material, each sphere names its entry. (Students need not
// change this file.)
struct Material {
    vec3 ambient;     // seen even where no light arrives
    vec3 diffuse;     // matte reflection, the same in every direction
    vec3 specular;    // shiny highlight colour
    float shininess;  // highlight exponent: larger = smaller, sharper highlight
};

uniform vec3 uMatAmbient[MAX_MATERIALS];
uniform vec3 uMatDiffuse[MAX_MATERIALS];
uniform vec3 uMatSpecular[MAX_MATERIALS];
uniform float uMatShininess[MAX_MATERIALS];
uniform int uSphereMaterial[MAX_SPHERES];   // material index of each sphere

Material materialOfSphere(int sphere)
{
    int m = uSphereMaterial[sphere];
    return Material(uMatAmbient[m], uMatDiffuse[m], uMatSpecular[m], uMatShininess[m]);
}
