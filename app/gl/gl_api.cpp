#include "gl/gl_api.h"

#include "core/error.h"

namespace gl {

#define RAYLAB_GL_DEFINE(type, name) type name = nullptr;
RAYLAB_GL_FUNCTIONS(RAYLAB_GL_DEFINE)
#undef RAYLAB_GL_DEFINE

void load(const ProcResolver& resolve) {
#define RAYLAB_GL_LOAD(type, name)                                                   \
    name = reinterpret_cast<type>(resolve("gl" #name));                             \
    if (!name) throw rl::Error("OpenGL function gl" #name " is not available from this context");
    RAYLAB_GL_FUNCTIONS(RAYLAB_GL_LOAD)
#undef RAYLAB_GL_LOAD
}

std::string errorName(GLenum error) {
    switch (error) {
        case GL_NO_ERROR: return "GL_NO_ERROR";
        case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
        case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
        case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
        case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
        case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
        default: return "GL error " + std::to_string(error);
    }
}

}  // namespace gl
