// Makes unfinished lab code visible. Every TODO stub calls labTodo(); the
// pixels whose computation reached a stub get magenta stripes, and the
// framework lists the open TODOs (file:line) when the shader is loaded.
// (Students need not change this file.)
bool gLabTodoReached = false;

void labTodo()
{
    gLabTodoReached = true;
}

// A stub reached earlier in the pipeline: vertex and geometry shaders pass a
// flat flag on to the fragment shader, which calls this with it.
void labTodoIf(bool reachedEarlier)
{
    if (reachedEarlier) gLabTodoReached = true;
}

#ifdef RAYLAB_FRAGMENT_SHADER
#ifdef RAYLAB_TODO_MARK
// The checks' second target: 1 where a stub was reached. Its alpha makes
// "over" blending keep a mark that an earlier layer wrote.
layout(location = 1) out vec4 labTodoMark;
#endif

// Call last in main(): adds the stripes where a stub was reached.
vec3 labOverlay(vec3 color)
{
#ifdef RAYLAB_TODO_MARK
    labTodoMark = gLabTodoReached ? vec4(1.0) : vec4(0.0);
#endif
    if (!gLabTodoReached) return color;
    bool stripe = mod(floor((gl_FragCoord.x + gl_FragCoord.y) / 12.0), 2.0) == 0.0;
    return stripe ? mix(color, vec3(1.0, 0.0, 1.0), 0.75) : color;
}
#endif
