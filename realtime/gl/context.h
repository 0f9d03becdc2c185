// A headless OpenGL 4.5 core context through EGL, with no display and no window: the EGL device
// platform on a hardware GPU, else Mesa's surfaceless platform (llvmpipe on the CPU). Every GL
// object in realtime/ lives in the one context that is current on the calling thread.
#pragma once

#include <memory>
#include <string>
#include <vector>

namespace gib::rt::gl {

// Which EGL device a context runs on, and what the driver says it is; recorded with every result.
struct GlIdentity {
  std::string device;    // "surfaceless" or "device N (<EGL device extensions summary>)"
  std::string vendor;    // GL_VENDOR
  std::string renderer;  // GL_RENDERER
  std::string version;   // GL_VERSION
  bool software = true;  // llvmpipe or another CPU rasterizer
};

struct ContextOptions {
  // "auto": the first hardware EGL device, else surfaceless; "surfaceless"; or a device index of
  // eglQueryDevicesEXT ("0", "1", ...). Empty means: $GIBENCH_GL_DEVICE, else "auto".
  std::string device;
  // KHR_debug output: GL errors are recorded (see Context::takeDebugErrors). On by default in
  // debug and sanitizer builds and in the tests; $GIBENCH_GL_DEBUG=1 turns it on anywhere.
  bool debug = false;
};

class Context {
 public:
  // Creates the context and makes it current on this thread. Throws gib::InputError with one
  // line naming what is missing (the Mesa EGL package, a device index out of range, ...).
  static std::unique_ptr<Context> create(ContextOptions options = {});
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  const GlIdentity& identity() const { return identity_; }
  bool debug() const { return debug_; }

  // GL errors reported through KHR_debug since the last call (with debug on), oldest first.
  std::vector<std::string> takeDebugErrors();

  // Makes this context current on the calling thread again.
  void makeCurrent();

 private:
  Context() = default;
  struct Egl;
  std::unique_ptr<Egl> egl_;
  GlIdentity identity_;
  bool debug_ = false;
  std::shared_ptr<std::vector<std::string>> debug_errors_;
};

// The default of ContextOptions::debug for this build: true unless NDEBUG, or with
// $GIBENCH_GL_DEBUG=1.
bool debugOutputByDefault();

}  // namespace gib::rt::gl
