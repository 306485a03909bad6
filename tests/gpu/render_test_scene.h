#pragma once
// A small scene for the render tests: a preset simulated on the CPU reference for a few
// frames, drawn by the real renderer into an offscreen target and read back. Set
// CSM_RENDER_TEST_DUMP=DIR to keep every image a test reads, for looking at.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "app/capture.h"
#include "app/frame_view.h"
#include "render/hair_renderer.h"
#include "render/position_source.h"
#include "app/preset.h"
#include "sim/run/make_solver.h"
#include "sim/run/simulation.h"
#include "tests/gpu/gl_fixture.h"

namespace csm::test {

// A preset from presets/, with fewer strands so the CPU reference steps it quickly.
inline Preset presetConfig(const std::string& name, int strands) {
  Preset c = defaultPreset();
  PresetErrors errors;
  const std::string path = CSM_SOURCE_DIR "/presets/" + name;
  INFO(errors.text());
  REQUIRE(loadPreset(path, c, errors));
  c.scene.hairstyle.strands = strands;
  return c;
}

struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;  // top to bottom
  const std::uint8_t* at(int x, int y) const {
    return &rgb[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 3];
  }
  double luma(int x, int y) const {
    const std::uint8_t* p = at(x, y);
    return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
  }
};

inline void dumpImage(const Image& image, const std::string& name) {
  const char* dir = std::getenv("CSM_RENDER_TEST_DUMP");
  if (!dir || !*dir) return;
  std::filesystem::create_directories(dir);
  std::string error;
  writePng((std::filesystem::path(dir) / (name + ".png")).string(), image.width, image.height,
           image.rgb, &error);
}

class RenderScene {
 public:
  // `sim`: a scene loaded already (on another solver); else the preset's on the CPU reference.
  explicit RenderScene(const Preset& preset, int frames = 2,
                       std::unique_ptr<Simulation> sim = nullptr)
      : preset_(preset), sim_(std::move(sim)) {
    glContext();
    std::string error;
    if (!sim_) {
      sim_ = std::make_unique<Simulation>(makeSolver("cpu", &error));
      INFO(error);
      REQUIRE(sim_->load(preset.scene, CSM_SOURCE_DIR "/presets", &error));
    }
    for (int f = 0; f < frames; ++f) sim_->stepFrame();
    renderer_ = HairRenderer::create(&error);
    INFO(error);
    REQUIRE(renderer_ != nullptr);
  }

  Simulation& sim() { return *sim_; }
  HairRenderer& renderer() { return *renderer_; }
  const Preset& preset() const { return preset_; }

  // Renders the current frame as `preset` says (default: the scene's own) and reads it back.
  // `withHair` false draws no strands: the backdrop and the head alone.
  // `amount`: how much of it to draw (default: everything, at the preset's quality).
  Image render(int width, int height, const Preset* preset = nullptr, bool withHair = true,
               const DrawAmount& amount = {}) {
    if (!target_ || target_->width() != width || target_->height() != height)
      target_ = std::make_unique<CaptureTarget>(width, height);
    const unsigned buffer = withHair ? positionsToDraw(*sim_, positions_) : 0;
    FrameView view =
        frameViewOf(*sim_, preset_.view, buffer, width, height, target_->framebuffer());
    if (preset) {
      view.scene = &preset->scene;
      view.look = &preset->view;
    }
    view.amount = amount;
    renderer_->render(view);
    Image image;
    image.width = width;
    image.height = height;
    image.rgb = target_->readRgb();
    return image;
  }

 private:
  Preset preset_;
  std::unique_ptr<Simulation> sim_;
  std::unique_ptr<HairRenderer> renderer_;
  std::unique_ptr<CaptureTarget> target_;
  PositionSource positions_;
};

// Pixels where `hair` differs from `bare` (the same frame drawn without strands).
inline std::vector<bool> hairMask(const Image& hair, const Image& bare, int threshold = 12) {
  std::vector<bool> mask(std::size_t(hair.width) * std::size_t(hair.height));
  for (int y = 0; y < hair.height; ++y)
    for (int x = 0; x < hair.width; ++x) {
      const std::uint8_t *a = hair.at(x, y), *b = bare.at(x, y);
      const int d = std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2]);
      mask[std::size_t(y) * std::size_t(hair.width) + std::size_t(x)] = d > threshold;
    }
  return mask;
}

}  // namespace csm::test
