// The one place that includes the OpenGL headers. Entry points come straight from GLVND's
// libOpenGL (core profile prototypes), so there is no loader; only realtime/ includes this.
#pragma once

#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/glcorearb.h>
