#pragma once
// The one place that includes OpenGL. Functions are the core-profile prototypes of
// <GL/glcorearb.h>, resolved at link time by libOSMesa (which exports the whole core API),
// so no loader is needed for the offscreen context. Include this only from .cpp files.
#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/glcorearb.h>
