// Headless OpenGL through EGL, with no window system and no surface: the
// device platform first (a GPU driver's device, NVIDIA included), then
// Mesa's surfaceless platform, then the default display. Render targets are
// framebuffer objects, so the context needs no surface at all.
#include "gl/context.h"

#include "core/error.h"
#include "gl/gl_api.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <vector>

namespace rl {
namespace {

const char* eglErrorName(EGLint e) {
    switch (e) {
        case EGL_SUCCESS: return "EGL_SUCCESS";
        case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
        case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
        case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
        case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
        case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
        case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
        case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
        case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
        case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
        default: return "EGL error";
    }
}

class EglContext final : public GlContext {
public:
    EglContext(EGLDisplay display, EGLContext context, EGLSurface surface, std::string platform)
        : display_(display), context_(context), surface_(surface) {
        gl::load([](const char* name) { return reinterpret_cast<void*>(eglGetProcAddress(name)); });
        description_ = detail::describeCurrentContext("EGL (" + platform + ")");
    }
    ~EglContext() override {
        eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        if (surface_ != EGL_NO_SURFACE) eglDestroySurface(display_, surface_);
        eglDestroyContext(display_, context_);
        eglTerminate(display_);
    }
    std::string description() const override { return description_; }

private:
    EGLDisplay display_;
    EGLContext context_;
    EGLSurface surface_;
    std::string description_;
};

bool hasExtension(const char* list, const char* name) {
    if (!list) return false;
    std::string all = std::string(" ") + list + " ";
    return all.find(std::string(" ") + name + " ") != std::string::npos;
}

// Makes a 3.3 core context current on an initialised display, or says why not.
std::unique_ptr<GlContext> contextOn(EGLDisplay display, const std::string& platform, std::string& why) {
    EGLint major = 0, minor = 0;
    if (!eglInitialize(display, &major, &minor)) {
        why = platform + ": eglInitialize failed (" + eglErrorName(eglGetError()) + ")";
        return nullptr;
    }
    if (!eglBindAPI(EGL_OPENGL_API)) {
        why = platform + ": no desktop OpenGL API";
        eglTerminate(display);
        return nullptr;
    }
    // Mesa surfaceless offers configs only with EGL_PBUFFER_BIT; a pbuffer of
    // 1x1 is the fallback where surfaceless contexts are not supported.
    const EGLint configAttribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                                    EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint count = 0;
    const char* extensions = eglQueryString(display, EGL_EXTENSIONS);
    if (!eglChooseConfig(display, configAttribs, &config, 1, &count) || count == 0) {
        if (!hasExtension(extensions, "EGL_KHR_no_config_context")) {
            why = platform + ": no pbuffer-capable OpenGL config";
            eglTerminate(display);
            return nullptr;
        }
        config = EGL_NO_CONFIG_KHR;
    }
    const EGLint contextAttribs[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
                                     EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                     EGL_NONE};
    EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, contextAttribs);
    if (context == EGL_NO_CONTEXT) {
        why = platform + ": no OpenGL 3.3 core context (" + eglErrorName(eglGetError()) + ")";
        eglTerminate(display);
        return nullptr;
    }
    EGLSurface surface = EGL_NO_SURFACE;
    if (!hasExtension(extensions, "EGL_KHR_surfaceless_context") && config != EGL_NO_CONFIG_KHR) {
        const EGLint pbufferAttribs[] = {EGL_WIDTH, 1, EGL_HEIGHT, 1, EGL_NONE};
        surface = eglCreatePbufferSurface(display, config, pbufferAttribs);
    }
    if (!eglMakeCurrent(display, surface, surface, context)) {
        why = platform + ": eglMakeCurrent failed (" + eglErrorName(eglGetError()) + ")";
        if (surface != EGL_NO_SURFACE) eglDestroySurface(display, surface);
        eglDestroyContext(display, context);
        eglTerminate(display);
        return nullptr;
    }
    try {
        return std::make_unique<EglContext>(display, context, surface, platform);
    } catch (const Error& e) {
        why = platform + ": " + e.what();
        eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(display, context);
        eglTerminate(display);
        return nullptr;
    }
}

}  // namespace

namespace detail {

std::unique_ptr<GlContext> createEglContext(std::string& why) {
    const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    auto getPlatformDisplay =
        reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    std::vector<std::string> reasons;

    // 1. The device platform: a GPU without any window system.
    auto queryDevices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    if (getPlatformDisplay && queryDevices && hasExtension(clientExtensions, "EGL_EXT_platform_device")) {
        EGLDeviceEXT devices[16];
        EGLint count = 0;
        if (queryDevices(16, devices, &count)) {
            auto queryDeviceString = reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(
                eglGetProcAddress("eglQueryDeviceStringEXT"));
            for (EGLint i = 0; i < count; ++i) {
                // Mesa lists its software device here too; prefer real GPUs and
                // leave software rendering to the surfaceless platform below.
                const char* ext = queryDeviceString ? queryDeviceString(devices[i], EGL_EXTENSIONS) : nullptr;
                if (hasExtension(ext, "EGL_MESA_device_software")) continue;
                EGLDisplay display = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
                if (display == EGL_NO_DISPLAY) continue;
                std::string reason;
                if (auto c = contextOn(display, "device platform", reason)) return c;
                reasons.push_back(reason);
            }
        }
        if (reasons.empty()) reasons.push_back("device platform: no GPU device");
    }
    // 2. Mesa's surfaceless platform (llvmpipe or a Mesa GPU driver).
    if (getPlatformDisplay && hasExtension(clientExtensions, "EGL_MESA_platform_surfaceless")) {
        EGLDisplay display = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        std::string reason;
        if (display != EGL_NO_DISPLAY) {
            if (auto c = contextOn(display, "surfaceless platform", reason)) return c;
            reasons.push_back(reason);
        }
    }
    // 3. Whatever the default display is.
    EGLDisplay display = eglGetDisplay(EGL_DEFAULT_DISPLAY);
    if (display != EGL_NO_DISPLAY) {
        std::string reason;
        if (auto c = contextOn(display, "default display", reason)) return c;
        reasons.push_back(reason);
    } else {
        reasons.push_back("default display: none");
    }
    why.clear();
    for (const auto& r : reasons) why += (why.empty() ? "" : ", ") + r;
    return nullptr;
}

}  // namespace detail
}  // namespace rl
