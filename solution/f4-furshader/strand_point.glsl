// A point of one strand of the fur shader. The strand grows from ROOT along
// the surface's NORMAL and bends toward GRAVITY, more and more toward its
// tip: at S (0 at the root, 1 at the tip) it is at
//     root + furLength * (s * normal + s^2 * gravity).
// (s^2: the strand's direction, the derivative normal + 2 s gravity, is the
// normal itself at the root and turns toward gravity along the way, so a
// strand leaves the skin straight and droops toward its tip.)
#include "lab_todo.glsl"

vec3 strandPoint(vec3 root, vec3 normal, float s, float furLength, vec3 gravity)
{
    //@open
    //@ // TODO(f4.a): a point of a strand.
    //@ // The point above. NORMAL may not be unit length; the strand's
    //@ // shape must not depend on its length.
    //@ // Checked by: raylab check --stage f4 (function strandPoint; view "fur-shader-shaggy").
    //@ labTodo();
    //@ return root + s * vec3(0.0, furLength, 0.0);  // until then: straight up
    //@guided
    // TODO(f4.a): return the point above. NORMAL may not be unit length.
    // Checked by: raylab check --stage f4 (function strandPoint, view
    // "fur-shader-shaggy").
    //@solution
    return root + furLength * (s * normalize(normal) + s * s * gravity);
    //@stub
    //@ labTodo();
    //@ return root + s * vec3(0.0, furLength, 0.0);  // until then: straight up
    //@end
    //@end-open
}
