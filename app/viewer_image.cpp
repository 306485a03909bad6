#include "app/viewer_image.h"

#include <cstdio>
#include <filesystem>

#include <png.h>

#include "gl/framebuffer.h"

namespace csm {

Image readWindowPixels(int width, int height) {
  Image image;
  if (width <= 0 || height <= 0) return image;
  std::vector<uint8_t> rgba(size_t(width) * height * 4);
  // Framebuffer 0 is the window's; wrap it only to read, and let go without deleting.
  gl::Framebuffer window = gl::Framebuffer::wrap(0);
  window.read(gl::Attachment::WindowBack, gl::Rect{0, 0, width, height}, gl::PixelFormat::Rgba,
              gl::PixelType::UnsignedByte, rgba.data());
  window.release();
  image.width = width;
  image.height = height;
  image.rgb.resize(size_t(width) * height * 3);
  for (int y = 0; y < height; ++y) {
    const uint8_t* src = &rgba[size_t(height - 1 - y) * width * 4];  // GL rows go bottom up
    uint8_t* dst = &image.rgb[size_t(y) * width * 3];
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < 3; ++c) dst[x * 3 + c] = src[x * 4 + c];
  }
  return image;
}

bool writePng(const std::string& path, const Image& image, std::string* error) {
  namespace fs = std::filesystem;
  auto fail = [&](const std::string& why) {
    if (error) *error = path + ": " + why;
    return false;
  };
  if (image.empty()) return fail("nothing to write (empty image)");
  const std::string temp = path + ".tmp";
  FILE* f = std::fopen(temp.c_str(), "wb");
  if (!f) return fail("cannot open for writing");
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!png || !info || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    std::fclose(f);
    std::remove(temp.c_str());
    return fail("libpng failed to encode the image");
  }
  png_init_io(png, f);
  png_set_IHDR(png, info, png_uint_32(image.width), png_uint_32(image.height), 8,
               PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
               PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  for (int y = 0; y < image.height; ++y)
    png_write_row(png, const_cast<png_bytep>(&image.rgb[size_t(y) * image.width * 3]));
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  const bool flushed = std::fflush(f) == 0;
  if (std::fclose(f) != 0 || !flushed) {
    std::remove(temp.c_str());
    return fail("write failed (disk full?)");
  }
  std::error_code ec;
  fs::rename(temp, path, ec);
  if (ec) {
    std::remove(temp.c_str());
    return fail("cannot rename the finished file into place: " + ec.message());
  }
  return true;
}

}  // namespace csm
