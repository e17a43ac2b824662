// Normal mapping: small bumps (mountains, craters) without more geometry.
// The sphere stays smooth; only the normal used for shading is tilted, as
// if the surface had bumps, so light and shade fall as on a bumpy surface.
// Key N turns it off.
//
// A normal map stores, per texel, a unit normal in the surface's own
// "tangent frame": x along T (growing u, east), y along B (growing v,
// north), z along the smooth normal N. A flat spot is (0, 0, 1). Colours
// hold 0..1, so each component c is stored as c * 0.5 + 0.5.
//
//          N (z)
//          |   tilted normal
//          |  /
//          | /
//          +-------- T (x)
//         /
//        B (y)
//
// To use it: read the texel, undo the encoding (* 2 - 1), and rotate it
// from the tangent frame into the world: n = T * x + B * y + N * z.
uniform int uNormalMaps;

void applyNormalMap(inout Surface s)
{
    if (uNormalMaps == 0 || s.material.normalMap < 0) return;
    //@open
    //@ // TODO(07.a): the normal tilted by the normal map.
    //@ // Tilt s.normal by the normal map (texel at s.uv of layer
    //@ // s.material.normalMap: textureLayer), as above. s.tangent points east
    //@ // (growing u) but need not be exactly perpendicular to the normal; the
    //@ // frame you build from it must be orthonormal (guide, section 3). The
    //@ // result is a unit vector.
    //@ // Checked by: raylab check --stage 07 (function applyNormalMap; views front, earth-closeup, moon-closeup).
    //@ labTodo();
    //@guided
    vec3 N = s.normal;

    // TODO(07.a): the tangent frame. s.tangent points east but need not be
    // exactly perpendicular to N: remove its part along N and normalise
    // (Gram-Schmidt), then B = cross(N, T) points north.
    // Checked by: raylab check --stage 07 (function applyNormalMap, views front, earth-closeup, moon-closeup).
    //@solution
    vec3 T = normalize(s.tangent - dot(s.tangent, N) * N);
    vec3 B = cross(N, T);
    //@stub
    //@ labTodo();
    //@ vec3 T = vec3(0.0);
    //@ vec3 B = vec3(0.0);
    //@end

    // TODO(07.b): read the normal map (textureLayer(s.material.normalMap,
    // s.uv).xyz), decode it to -1..1, rotate it into the world with T, B, N
    // and store the normalised result in s.normal.
    // Checked by: raylab check --stage 07 (function applyNormalMap, views front, earth-closeup, moon-closeup).
    //@solution
    vec3 m = textureLayer(s.material.normalMap, s.uv).xyz * 2.0 - 1.0;
    s.normal = normalize(T * m.x + B * m.y + N * m.z);
    //@stub
    //@ labTodo();
    //@end
    //@end-open
}
