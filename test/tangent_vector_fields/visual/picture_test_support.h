// Copyright (c) 2026 The Tangent_vector_fields authors.
// SPDX-License-Identifier: GPL-3.0-or-later

// What the picture tests share: PNG files read back into pixels, pixel comparisons and a
// camera that looks straight down the z axis.

#ifndef TVF_PICTURE_TEST_SUPPORT_H
#define TVF_PICTURE_TEST_SUPPORT_H

#include <CGAL/Tangent_vector_fields/Field_renderer.h>

#include <cairo.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace tvf_picture_test {

namespace TVF = CGAL::Tangent_vector_fields;

struct Image
{
  int width = 0, height = 0;
  std::vector<std::uint32_t> pixels; // 0xAARRGGBB
  std::uint32_t at(int x, int y) const { return pixels[static_cast<std::size_t>(y) * width + x]; }
  static int red(std::uint32_t p) { return (p >> 16) & 255; }
  static int green(std::uint32_t p) { return (p >> 8) & 255; }
  static int blue(std::uint32_t p) { return p & 255; }
};

// The pixels of a PNG file. A file that cannot be read is a failure of the test, never an empty
// image: an empty image would compare equal to any other.
inline Image read_png(const std::string& file)
{
  cairo_surface_t* s = cairo_image_surface_create_from_png(file.c_str());
  const cairo_status_t status = cairo_surface_status(s);
  if(status != CAIRO_STATUS_SUCCESS)
  {
    cairo_surface_destroy(s);
    throw std::runtime_error("cannot read the picture " + file + ": " + cairo_status_to_string(status));
  }
  Image image;
  cairo_surface_flush(s);
  image.width = cairo_image_surface_get_width(s);
  image.height = cairo_image_surface_get_height(s);
  const int stride = cairo_image_surface_get_stride(s);
  const unsigned char* data = cairo_image_surface_get_data(s);
  for(int y = 0; y < image.height; ++y)
    for(int x = 0; x < image.width; ++x)
      image.pixels.push_back(reinterpret_cast<const std::uint32_t*>(data + static_cast<std::size_t>(y) * stride)[x]);
  cairo_surface_destroy(s);
  return image;
}

// Pixels that differ in colour; pictures of different sizes are not comparable.
inline int count_differences(const Image& a, const Image& b)
{
  if(a.width != b.width || a.height != b.height)
    throw std::runtime_error("pictures of different sizes: " + std::to_string(a.width) + "x" + std::to_string(a.height) +
                             " and " + std::to_string(b.width) + "x" + std::to_string(b.height));
  int n = 0;
  for(std::size_t i = 0; i < a.pixels.size(); ++i) n += (a.pixels[i] & 0xffffff) != (b.pixels[i] & 0xffffff);
  return n;
}

inline TVF::Render_options front_view(int width, int height)
{
  TVF::Render_options o;
  o.width = width;
  o.height = height;
  o.camera.projection = TVF::Projection::orthographic;
  o.camera.view_direction = {0, 0, -1}; // the camera on +z, looking down the z axis; y up
  o.legend = false;
  return o;
}

const std::uint32_t white = 0xffffffu; // the background

} // namespace tvf_picture_test

#endif
