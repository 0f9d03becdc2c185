// Under LeakSanitizer, the leak check at the end of main, while every thread is idle.
//
// LSan's own check runs from an atexit handler, after the static destructors of the program and
// its libraries: oneTBB (Embree's scheduler, and OpenVDB's under OpenImageIO) releases its worker
// threads there without joining them, so the check's stop-the-world tracer can meet a thread that
// is half gone and crash ("Tracer caught signal 11"), failing a process that leaked nothing.
// Checking at the end of main, before any teardown, sees the same heap with every thread parked;
// LSan then skips its exit-time check. Without the sanitizer this does nothing.
#pragma once

#if defined(__SANITIZE_ADDRESS__)
#define GIB_HAS_LEAK_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(leak_sanitizer)
#define GIB_HAS_LEAK_SANITIZER 1
#endif
#endif

#if defined(GIB_HAS_LEAK_SANITIZER)
#include <sanitizer/lsan_interface.h>
#endif

namespace gib {

// Reports leaks (and exits with LSan's exit code) now rather than at exit.
inline void checkLeaksWhileQuiescent() {
#if defined(GIB_HAS_LEAK_SANITIZER)
  __lsan_do_leak_check();
#endif
}

}  // namespace gib
