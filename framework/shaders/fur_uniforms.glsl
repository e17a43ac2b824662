// The fur track's uniforms, set by the framework's fur renderer for every
// draw. World space throughout: y is up. (Students need not change this file.)
// (A function check runs one of your functions on its own and sets these
// itself: RAYLAB_FUNCTION_CHECK makes them plain variables there.)
#ifdef RAYLAB_FUNCTION_CHECK
#define FUR_UNIFORM
#else
#define FUR_UNIFORM uniform
#endif
FUR_UNIFORM mat4 uModel;       // object space -> world space
FUR_UNIFORM mat4 uView;        // world space -> camera space
FUR_UNIFORM mat4 uProjection;  // camera space -> clip space
FUR_UNIFORM vec3 uEye;         // the camera's position
FUR_UNIFORM vec3 uLightDir;    // unit vector toward the (directional) light
FUR_UNIFORM vec3 uLightColor;
FUR_UNIFORM vec3 uAmbient;     // light that reaches every point

uniform float uFurLength;  // how far the tips stand off the skin
uniform int uShellIndex;   // which of the shell draw calls this is: 0 (the first) .. uShellCount - 1
uniform int uShellCount;   // draw calls of the shell program per frame, the skin's included
uniform float uPatternScale;     // fur pattern repeats per unit of texture coordinate
uniform float uShadowIntensity;  // how much darker the fur is at its roots (0..1)
uniform vec3 uGravity;           // stage f4: the pull on a strand, as a share of its length
uniform float uStrandDensity;    // stage f4: strand roots per unit of area

uniform sampler2D uColorMap;  // the coat's colour
uniform sampler2D uPattern;   // grey: where the hairs are, and how tall (white: tall)
uniform sampler2D uFinMap;    // strands seen from the side; alpha is coverage
