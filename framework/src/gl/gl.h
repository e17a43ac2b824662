#pragma once
// The one place that includes the OpenGL headers (GLEW first, as it requires).
#include <GL/glew.h>
