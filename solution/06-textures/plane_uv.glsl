// Texture coordinates on a plane: two perpendicular directions in the plane
// (axisU, axisV), and the distance along each from a point of the plane,
// divided by the tile size, so the picture repeats every `tile` units.

// Two unit vectors in the plane with normal n, with cross(axisU, axisV) = n
// (so the picture is not mirrored seen from the front). (Provided.)
void planeAxes(vec3 n, out vec3 axisU, out vec3 axisV)
{
    vec3 helper = abs(n.z) < 0.9 ? vec3(0.0, 0.0, 1.0) : vec3(1.0, 0.0, 0.0);
    axisU = normalize(cross(n, helper));
    axisV = cross(n, axisU);
}

vec2 planeUV(vec3 point, vec3 origin, vec3 n, float tile)
{
    //@open
    //@ // TODO(06.b): texture coordinates on a plane.
    //@ // (u, v) of `point` on the plane with unit normal n through
    //@ // `origin`: its distances from `origin` along planeAxes' axisU and axisV,
    //@ // in tiles of `tile` units. The texture repeats by itself (GL_REPEAT): u
    //@ // and v may grow without bound.
    //@ // Checked by: raylab check --stage 06 (function planeUV; views front, floor-closeup).
    //@ labTodo();
    //@ return vec2(0.0);
    //@guided
    // TODO(06.b): project point - origin onto the two axes from planeAxes
    // and divide by the tile size. The texture repeats by itself (its wrap
    // mode is GL_REPEAT), so u and v may grow without bound.
    // Checked by: raylab check --stage 06 (function planeUV, views front, floor-closeup).
    //@solution
    vec3 axisU, axisV;
    planeAxes(n, axisU, axisV);
    vec3 offset = point - origin;
    return vec2(dot(offset, axisU), dot(offset, axisV)) / tile;
    //@stub
    //@ labTodo();
    //@ return vec2(0.0);
    //@end
    //@end-open
}
