// Framebuffers: clear and read back, layered 2D arrays, multisample resolve, and a draw.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gl/caps.h"
#include "gl/framebuffer.h"
#include "gl/renderbuffer.h"
#include "gl/shader_source.h"
#include "gl/texture.h"
#include "gl/vertex_array.h"
#include "tests/gpu/gl_fixture.h"

using namespace csm;

TEST_CASE("GL: a framebuffer with a color texture is cleared and read back",
          "[gl][framebuffer][quick]") {
  test::glContext();
  const GLsizei w = 37, h = 21;  // odd sizes catch row-alignment mistakes

  SECTION("RGBA8") {
    gl::Texture color = gl::Texture::create2D(GL_RGBA8, w, h);
    gl::Framebuffer fb;
    fb.attach(GL_COLOR_ATTACHMENT0, color);
    std::string message;
    REQUIRE(fb.checkComplete(&message));
    CHECK(message.empty());

    fb.clearColor(0, std::array<float, 4>{1.0f, 0.0f, 0.2f, 1.0f});
    std::vector<std::uint8_t> pixels =
        fb.read<std::uint8_t>(GL_COLOR_ATTACHMENT0, {0, 0, w, h}, GL_RGBA, GL_UNSIGNED_BYTE, 4);
    REQUIRE(pixels.size() == std::size_t(w * h * 4));
    for (std::size_t i = 0; i < pixels.size(); i += 4) {
      REQUIRE(pixels[i] == 255);
      REQUIRE(pixels[i + 1] == 0);
      REQUIRE(pixels[i + 2] == 51);
      REQUIRE(pixels[i + 3] == 255);
    }
    // The texture's own readback sees the same.
    CHECK(color.read<std::uint8_t>(GL_RGBA, GL_UNSIGNED_BYTE, 4) == pixels);
  }
  SECTION("RGBA32F, plus depth") {
    gl::Texture color = gl::Texture::create2D(GL_RGBA32F, w, h);
    gl::Renderbuffer depth(GL_DEPTH_COMPONENT24, w, h);
    gl::Framebuffer fb;
    fb.attach(GL_COLOR_ATTACHMENT0, color).attach(GL_DEPTH_ATTACHMENT, depth);
    REQUIRE(fb.checkComplete());
    fb.clearColor(0, std::array<float, 4>{0.125f, -3.5f, 1e6f, 0.0f});
    fb.clearDepth();
    std::vector<float> pixels =
        fb.read<float>(GL_COLOR_ATTACHMENT0, {5, 6, 3, 2}, GL_RGBA, GL_FLOAT, 4);
    for (std::size_t i = 0; i < pixels.size(); i += 4)
      REQUIRE(glm::vec4(pixels[i], pixels[i + 1], pixels[i + 2], pixels[i + 3]) ==
              glm::vec4(0.125f, -3.5f, 1e6f, 0.0f));
  }
  CHECK(gl::checkErrors("framebuffer test"));
}

TEST_CASE("GL: an incomplete framebuffer says why", "[gl][framebuffer][quick]") {
  test::glContext();
  gl::Framebuffer empty;
  std::string message;
  CHECK_FALSE(empty.checkComplete(&message));
  CHECK(message.find("GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT") != std::string::npos);
  gl::Framebuffer::bindDefault();
}

TEST_CASE("GL: 2D array textures attach layered or one layer at a time",
          "[gl][framebuffer][quick]") {
  test::glContext();
  gl::Texture layers = gl::Texture::create2DArray(GL_R32F, 8, 4, 3);
  CHECK(layers.layers() == 3);

  gl::Framebuffer all;
  all.attach(GL_COLOR_ATTACHMENT0, layers);  // layered: a clear reaches every layer
  REQUIRE(all.checkComplete());
  all.clearColor(0, std::array<float, 4>{7.0f, 0, 0, 0});

  gl::Framebuffer one;
  one.attachLayer(GL_COLOR_ATTACHMENT0, layers, 1);
  REQUIRE(one.checkComplete());
  one.clearColor(0, std::array<float, 4>{-1.0f, 0, 0, 0});

  std::vector<float> texels = layers.read<float>(GL_RED, GL_FLOAT, 1);
  REQUIRE(texels.size() == 8 * 4 * 3);
  for (std::size_t i = 0; i < texels.size(); ++i)
    REQUIRE(texels[i] == (i / 32 == 1 ? -1.0f : 7.0f));
  CHECK(gl::checkErrors("2D array test"));
}

TEST_CASE("GL: a multisample target resolves by blit", "[gl][framebuffer][quick]") {
  test::glContext();
  // OpenGL 4.3 requires GL_MAX_SAMPLES of at least 4 (the spec's table of implementation
  // minimums), and the renderer's MSAA relies on it: a driver with less fails here.
  const GLsizei samples = std::min<GLsizei>(4, gl::queryCaps().maxSamples);
  INFO("GL_MAX_SAMPLES " << gl::queryCaps().maxSamples);
  REQUIRE(samples >= 4);
  gl::Renderbuffer msColor(GL_RGBA8, 16, 16, samples);
  gl::Framebuffer ms;
  ms.attach(GL_COLOR_ATTACHMENT0, msColor);
  REQUIRE(ms.checkComplete());
  ms.clearColor(0, std::array<float, 4>{0.0f, 1.0f, 0.0f, 1.0f});

  gl::Texture msTexture = gl::Texture::create2DMultisample(GL_RGBA8, 16, 16, samples);
  gl::Framebuffer msTex;
  msTex.attach(GL_COLOR_ATTACHMENT0, msTexture);
  CHECK(msTex.checkComplete());

  gl::Texture resolved = gl::Texture::create2D(GL_RGBA8, 16, 16);
  gl::Framebuffer single;
  single.attach(GL_COLOR_ATTACHMENT0, resolved);
  REQUIRE(single.checkComplete());
  ms.blitTo(single.id(), {0, 0, 16, 16}, {0, 0, 16, 16});
  std::vector<std::uint8_t> pixels = resolved.read<std::uint8_t>(GL_RGBA, GL_UNSIGNED_BYTE, 4);
  CHECK(pixels[0] == 0);
  CHECK(pixels[1] == 255);
  CHECK(pixels[pixels.size() - 3] == 255);
  CHECK(gl::checkErrors("multisample test"));
}

TEST_CASE("GL: an attribute-less draw into a framebuffer", "[gl][framebuffer][draw][quick]") {
  test::glContext();
  std::string log;
  std::optional<gl::Program> program = gl::buildProgram(
      "solid",
      {{GL_VERTEX_SHADER, "test/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "test/solid.frag"}}, {},
      &log);
  INFO(log);
  REQUIRE(program);
  program->setUniform("color", glm::vec4(0.0f, 0.0f, 1.0f, 1.0f));

  gl::Texture color = gl::Texture::create2D(GL_RGBA8, 32, 32);
  gl::Framebuffer fb;
  fb.attach(GL_COLOR_ATTACHMENT0, color).setDrawBuffers({GL_COLOR_ATTACHMENT0});
  REQUIRE(fb.checkComplete());
  fb.clearColor(0, std::array<float, 4>{1, 1, 1, 1});

  gl::VertexArray empty;
  fb.bind();
  glViewport(0, 0, 32, 32);
  program->use();
  empty.bind();
  glDrawArrays(GL_TRIANGLES, 0, 3);
  gl::VertexArray::unbind();

  std::vector<std::uint8_t> pixels = color.read<std::uint8_t>(GL_RGBA, GL_UNSIGNED_BYTE, 4);
  for (std::size_t i = 0; i < pixels.size(); i += 4)
    REQUIRE(std::array<int, 4>{pixels[i], pixels[i + 1], pixels[i + 2], pixels[i + 3]} ==
            std::array<int, 4>{0, 0, 255, 255});
  gl::Framebuffer::bindDefault();
  CHECK(gl::checkErrors("draw test"));
}
