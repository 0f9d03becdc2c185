#include "realtime/gl/context.h"

#include "common/environment_error.h"
#include "common/input_error.h"
#include "realtime/gl/fault_injection.h"
#include "realtime/gl/gl.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <fmt/format.h>

#include <cstdlib>
#include <cstring>
#include <optional>
#include <string_view>

namespace gib::rt::gl {

namespace {

constexpr const char* kMesaHint =
    "install Mesa's EGL and software rasterizer (apt install libegl-mesa0 libgl1-mesa-dri, as "
    "scripts/install-deps.sh does)";

bool hasExtension(const char* extensions, std::string_view name) {
  if (!extensions) return false;
  std::string_view all(extensions);
  for (std::size_t start = 0; start < all.size();) {
    std::size_t end = all.find(' ', start);
    if (end == std::string_view::npos) end = all.size();
    if (all.substr(start, end - start) == name) return true;
    start = end + 1;
  }
  return false;
}

template <typename F>
F eglProc(const char* name) {
  return reinterpret_cast<F>(eglGetProcAddress(name));
}

std::string eglErrorName(EGLint error) {
  switch (error) {
    case EGL_NOT_INITIALIZED:
      return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS:
      return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC:
      return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE:
      return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG:
      return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT:
      return "EGL_BAD_CONTEXT";
    case EGL_BAD_DISPLAY:
      return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH:
      return "EGL_BAD_MATCH";
    case EGL_BAD_PARAMETER:
      return "EGL_BAD_PARAMETER";
    default:
      return fmt::format("EGL error 0x{:04x}", error);
  }
}

struct DeviceList {
  std::vector<EGLDeviceEXT> devices;
  std::vector<std::string> extensions;  // per device
};

DeviceList queryDevices() {
  DeviceList list;
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!hasExtension(client, "EGL_EXT_device_enumeration") &&
      !hasExtension(client, "EGL_EXT_device_base"))
    return list;
  auto query_devices = eglProc<PFNEGLQUERYDEVICESEXTPROC>("eglQueryDevicesEXT");
  auto query_string = eglProc<PFNEGLQUERYDEVICESTRINGEXTPROC>("eglQueryDeviceStringEXT");
  if (!query_devices || !query_string) return list;
  EGLint count = 0;
  if (!query_devices(0, nullptr, &count) || count <= 0) return list;
  list.devices.resize(std::size_t(count));
  query_devices(count, list.devices.data(), &count);
  list.devices.resize(std::size_t(count));
  for (EGLDeviceEXT device : list.devices) {
    const char* ext = query_string(device, EGL_EXTENSIONS);
    list.extensions.emplace_back(ext ? ext : "");
  }
  return list;
}

bool isSoftwareDevice(const std::string& extensions) {
  return hasExtension(extensions.c_str(), "EGL_MESA_device_software");
}

}  // namespace

struct Context::Egl {
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLContext context = EGL_NO_CONTEXT;
};

namespace {

// One attempt at a 4.5 core context on `display`; returns an empty optional with the reason.
std::optional<std::string> createOn(EGLDisplay display, bool debug, EGLContext* out) {
  EGLint major = 0, minor = 0;
  if (display == EGL_NO_DISPLAY) return "no EGL display";
  if (!eglInitialize(display, &major, &minor))
    return fmt::format("eglInitialize failed ({})", eglErrorName(eglGetError()));
  const char* extensions = eglQueryString(display, EGL_EXTENSIONS);
  if (!hasExtension(extensions, "EGL_KHR_surfaceless_context"))
    return "the EGL display cannot make a context current without a surface";
  if (!eglBindAPI(EGL_OPENGL_API)) return "the EGL display has no desktop OpenGL";
  EGLConfig config = EGL_NO_CONFIG_KHR;
  if (!hasExtension(extensions, "EGL_KHR_no_config_context")) {
    const EGLint attributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLint count = 0;
    if (!eglChooseConfig(display, attributes, &config, 1, &count) || count == 0)
      return "no EGL configuration supports desktop OpenGL";
  }
  const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                               4,
                               EGL_CONTEXT_MINOR_VERSION,
                               5,
                               EGL_CONTEXT_OPENGL_PROFILE_MASK,
                               EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                               EGL_CONTEXT_OPENGL_DEBUG,
                               debug ? EGL_TRUE : EGL_FALSE,
                               EGL_NONE};
  EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, attributes);
  if (context == EGL_NO_CONTEXT)
    return fmt::format("no OpenGL 4.5 core context ({})", eglErrorName(eglGetError()));
  if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
    eglDestroyContext(display, context);
    return fmt::format("eglMakeCurrent failed ({})", eglErrorName(eglGetError()));
  }
  *out = context;
  return std::nullopt;
}

std::string glString(GLenum name) {
  const GLubyte* s = glGetString(name);
  return s ? reinterpret_cast<const char*>(s) : "";
}

void APIENTRY recordDebugMessage(GLenum /*source*/, GLenum type, GLuint id, GLenum severity,
                                 GLsizei length, const GLchar* message, const void* user) {
  // Only errors and undefined behaviour fail a run; performance notes and markers do not.
  if (type != GL_DEBUG_TYPE_ERROR && type != GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR) return;
  (void)severity;
  auto* errors = static_cast<std::vector<std::string>*>(const_cast<void*>(user));
  errors->push_back(
      fmt::format("GL error {}: {}", id, std::string_view(message, std::size_t(length))));
}

}  // namespace

bool debugOutputByDefault() {
  const char* env = std::getenv("GIBENCH_GL_DEBUG");
  if (env && *env) return std::string_view(env) != "0";
#ifdef NDEBUG
  return false;
#else
  return true;
#endif
}

std::unique_ptr<Context> Context::create(ContextOptions options) {
  if (glFaultInjected(GlFault::kContext))
    throw EnvironmentError("cannot create a GL context: injected by GIB_GL_FAULT=context");
  std::string choice = options.device;
  if (choice.empty()) {
    const char* env = std::getenv("GIBENCH_GL_DEVICE");
    choice = env && *env ? env : "auto";
  }
  if (eglQueryString(EGL_NO_DISPLAY, EGL_VERSION) == nullptr &&
      eglGetProcAddress("eglGetPlatformDisplayEXT") == nullptr)
    throw InputError(fmt::format("no EGL implementation is installed; {}", kMesaHint));
  auto get_platform_display = eglProc<PFNEGLGETPLATFORMDISPLAYEXTPROC>("eglGetPlatformDisplayEXT");
  if (!get_platform_display)
    throw InputError(fmt::format("EGL lacks eglGetPlatformDisplayEXT; {}", kMesaHint));

  const DeviceList devices = queryDevices();
  std::unique_ptr<Context> result(new Context());
  result->egl_ = std::make_unique<Egl>();
  result->debug_ = options.debug;
  std::vector<std::string> failures;

  auto try_device = [&](std::size_t index) {
    EGLDisplay display =
        get_platform_display(EGL_PLATFORM_DEVICE_EXT, devices.devices[index], nullptr);
    if (auto failure = createOn(display, options.debug, &result->egl_->context)) {
      failures.push_back(fmt::format("device {}: {}", index, *failure));
      return false;
    }
    result->egl_->display = display;
    result->identity_.device = fmt::format("device {}", index);
    return true;
  };
  auto try_surfaceless = [&] {
    const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!hasExtension(client, "EGL_MESA_platform_surfaceless")) {
      failures.push_back("Mesa's surfaceless platform is not available");
      return false;
    }
    EGLDisplay display =
        get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (auto failure = createOn(display, options.debug, &result->egl_->context)) {
      failures.push_back(fmt::format("surfaceless: {}", *failure));
      return false;
    }
    result->egl_->display = display;
    result->identity_.device = "surfaceless";
    return true;
  };

  bool created = false;
  if (choice == "auto") {
    for (std::size_t i = 0; i < devices.devices.size() && !created; ++i)
      if (!isSoftwareDevice(devices.extensions[i])) created = try_device(i);
    if (!created) created = try_surfaceless();
  } else if (choice == "surfaceless") {
    created = try_surfaceless();
  } else {
    char* end = nullptr;
    const long index = std::strtol(choice.c_str(), &end, 10);
    if (choice.empty() || *end != '\0' || index < 0)
      throw InputError(fmt::format(
          "GL device '{}' is not 'auto', 'surfaceless' or a device index; set GIBENCH_GL_DEVICE "
          "to one of those",
          choice));
    if (std::size_t(index) >= devices.devices.size())
      throw InputError(fmt::format(
          "GL device {} does not exist: EGL lists {} device(s); use an index below that, "
          "'surfaceless' or 'auto'",
          index, devices.devices.size()));
    created = try_device(std::size_t(index));
  }
  if (!created) {
    std::string reasons;
    for (const std::string& f : failures) reasons += (reasons.empty() ? "" : "; ") + f;
    throw InputError(
        fmt::format("cannot create a headless OpenGL 4.5 context ({}); {}", reasons, kMesaHint));
  }

  GlIdentity& id = result->identity_;
  id.vendor = glString(GL_VENDOR);
  id.renderer = glString(GL_RENDERER);
  id.version = glString(GL_VERSION);
  id.software = id.renderer.find("llvmpipe") != std::string::npos ||
                id.renderer.find("softpipe") != std::string::npos ||
                id.renderer.find("SwiftShader") != std::string::npos;

  result->debug_errors_ = std::make_shared<std::vector<std::string>>();
  if (options.debug) {
    // Context-wide and set once, here: no pass's pipeline state (pipeline_state.h).
    glEnable(GL_DEBUG_OUTPUT);
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageCallback(recordDebugMessage, result->debug_errors_.get());
    glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_TRUE);
  }
  return result;
}

Context::~Context() {
  if (!egl_ || egl_->context == EGL_NO_CONTEXT) return;
  if (debug_) glDebugMessageCallback(nullptr, nullptr);
  eglMakeCurrent(egl_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(egl_->display, egl_->context);
  // The display is left initialised: EGL returns the same display to every caller in this
  // process, and terminating it would pull it from under any other live context.
}

void Context::makeCurrent() {
  eglMakeCurrent(egl_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, egl_->context);
}

std::vector<std::string> Context::takeDebugErrors() {
  // glGetError also catches what a driver without KHR_debug reports.
  for (GLenum e = glGetError(); e != GL_NO_ERROR; e = glGetError())
    debug_errors_->push_back(fmt::format("glGetError 0x{:04x}", e));
  std::vector<std::string> errors;
  errors.swap(*debug_errors_);
  return errors;
}

}  // namespace gib::rt::gl
