#pragma once
// The OpenGL 3.3 core API for the renderer's files. OSMesa's library exports every core entry
// point, so the prototypes are linked directly (no loader). Also: error checks with context.
#define GL_GLEXT_PROTOTYPES 1
#include <GL/glcorearb.h>

#include <string>

namespace cablefilm {

// Throws Error naming `where` and every pending GL error code.
void CheckGl(const std::string& where);

}  // namespace cablefilm
