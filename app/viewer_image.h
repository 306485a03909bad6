// What the window shows, read back after the UI is drawn: the screenshot key and
// --screenshot both save one of these.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace csm {

struct Image {
  int width = 0, height = 0;
  std::vector<uint8_t> rgb;  // rows top to bottom, 3 bytes a pixel

  bool empty() const { return rgb.empty(); }
  const uint8_t* pixel(int x, int y) const { return &rgb[(size_t(y) * width + x) * 3]; }
};

// The default framebuffer's back buffer (call after drawing, before the swap). Waits for the
// GPU: only on request, never every frame.
Image readWindowPixels(int width, int height);

// An 8-bit RGB PNG, written beside `path` and renamed over it, so a reader never sees half a
// file. False with a message on failure.
bool writePng(const std::string& path, const Image& image, std::string* error);

}  // namespace csm
