#pragma once
// A rendered PNG read back into pixels, for the map tests.
#include <cairo.h>

#include <algorithm>
#include <cstdint>
#include <string>

#include "worker/map/map_layout.h"

namespace rlpos::map::testing {

class Image {
 public:
  explicit Image(const std::string& png) : bytes_(png) {
    surface_ = cairo_image_surface_create_from_png_stream(&Image::Read, this);
  }
  ~Image() { cairo_surface_destroy(surface_); }
  Image(const Image&) = delete;
  Image& operator=(const Image&) = delete;
  bool ok() const { return cairo_surface_status(surface_) == CAIRO_STATUS_SUCCESS; }
  int width() const { return cairo_image_surface_get_width(surface_); }
  int height() const { return cairo_image_surface_get_height(surface_); }
  // 0xRRGGBB of the pixel under the canvas point (x, y), in points.
  std::uint32_t At(double x, double y) const {
    const int px = static_cast<int>(x * kPngPixelsPerPoint);
    const int py = static_cast<int>(y * kPngPixelsPerPoint);
    const unsigned char* row =
        cairo_image_surface_get_data(surface_) + py * cairo_image_surface_get_stride(surface_);
    return reinterpret_cast<const std::uint32_t*>(row)[px] & 0xffffff;
  }
  // The pixel under the venue point `p` in `view`.
  std::uint32_t At(const View& view, const Vec3& p) const {
    return At(view.CanvasX(p), view.CanvasY(p));
  }

 private:
  static cairo_status_t Read(void* closure, unsigned char* data, unsigned int length) {
    Image* self = static_cast<Image*>(closure);
    if (self->offset_ + length > self->bytes_.size())
      return CAIRO_STATUS_READ_ERROR;
    std::copy_n(self->bytes_.data() + self->offset_, length, data);
    self->offset_ += length;
    return CAIRO_STATUS_SUCCESS;
  }
  std::string bytes_;
  std::size_t offset_ = 0;
  cairo_surface_t* surface_ = nullptr;
};

}  // namespace rlpos::map::testing
