// The canvas: two triangles that cover the screen. Each corner is placed on a
// virtual canvas in front of the eye; the direction from the eye to it is
// interpolated across the triangles, so every fragment gets the primary ray
// through its own pixel centre. (Students need not change this file.)
layout(location = 0) in vec2 aCorner;  // (-1,-1) .. (1,1)

uniform vec3 uEye;
uniform vec3 uForward;  // unit view direction
uniform vec3 uRight;    // unit, to the right of the view
uniform vec3 uUp;       // unit, up in the image
uniform float uFocal;   // eye-to-canvas distance for a canvas of half-height 1
uniform float uAspect;  // width / height

out vec3 vsRay;

void main()
{
    gl_Position = vec4(aCorner, 0.0, 1.0);
    // The corner relative to the eye, never uEye + ... - uEye: far from the
    // origin that difference cancels and loses digits of the direction.
    vsRay = uForward * uFocal + uRight * (uAspect * aCorner.x) + uUp * aCorner.y;
}
