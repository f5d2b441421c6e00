// Headless OpenGL through Mesa's OSMesa: the fallback where EGL is missing.
// (Mesa 25.1 removed OSMesa, so EGL is the main path.) OSMesa needs a colour
// buffer to be current; raylab renders into framebuffer objects, so a 1x1
// buffer is enough.
#include "gl/context.h"

#include "core/error.h"
#include "gl/gl_api.h"

#include <GL/osmesa.h>

namespace rl {
namespace {

class OsMesaContext final : public GlContext {
public:
    explicit OsMesaContext(OSMesaContext context) : context_(context) {
        if (!OSMesaMakeCurrent(context_, buffer_, GL_UNSIGNED_BYTE, 1, 1))
            throw Error("OSMesaMakeCurrent failed");
        gl::load([](const char* name) { return reinterpret_cast<void*>(OSMesaGetProcAddress(name)); });
        description_ = detail::describeCurrentContext("OSMesa");
    }
    ~OsMesaContext() override { OSMesaDestroyContext(context_); }
    std::string description() const override { return description_; }

private:
    OSMesaContext context_;
    unsigned char buffer_[4] = {0, 0, 0, 0};
    std::string description_;
};

}  // namespace

namespace detail {

std::unique_ptr<GlContext> createOsMesaContext(std::string& why) {
    const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 0, OSMESA_PROFILE,
                           OSMESA_CORE_PROFILE, OSMESA_CONTEXT_MAJOR_VERSION, 3,
                           OSMESA_CONTEXT_MINOR_VERSION, 3, 0};
    OSMesaContext context = OSMesaCreateContextAttribs(attribs, nullptr);
    if (!context) {
        why = "OSMesaCreateContextAttribs gave no OpenGL 3.3 core context";
        return nullptr;
    }
    try {
        return std::make_unique<OsMesaContext>(context);
    } catch (const Error& e) {
        OSMesaDestroyContext(context);
        why = e.what();
        return nullptr;
    }
}

}  // namespace detail
}  // namespace rl
