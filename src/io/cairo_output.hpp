#pragma once
// Owning cairo handles and "surface to bytes" for the figure writers, which write the bytes
// atomically so no half-drawn file is ever left behind.
#include <cairo-svg.h>
#include <cairo.h>
#include <dlfcn.h>

#include <memory>
#include <string>

namespace pak::cairo_output {

struct SurfaceDeleter {
  void operator()(cairo_surface_t* surface) const { cairo_surface_destroy(surface); }
};
struct ContextDeleter {
  void operator()(cairo_t* context) const { cairo_destroy(context); }
};
using SurfacePtr = std::unique_ptr<cairo_surface_t, SurfaceDeleter>;
using ContextPtr = std::unique_ptr<cairo_t, ContextDeleter>;

inline cairo_status_t appendToString(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

// Cairo's text keeps process-wide font caches (its own and fontconfig's) that are never freed,
// which leak checkers report. After a figure with text is done, drop them: the next text
// rebuilds them. Fontconfig is reached through cairo's own dependency, so Pak need not link
// it; not for use while another thread draws text.
inline void releaseFontCaches() {
  cairo_debug_reset_static_data();
  if (void* fini = dlsym(RTLD_DEFAULT, "FcFini")) reinterpret_cast<void (*)()>(fini)();
}

}  // namespace pak::cairo_output
