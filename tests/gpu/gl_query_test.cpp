// Timer queries and the per-stage timer.
#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec4.hpp>

#include "gl/framebuffer.h"
#include "gl/texture.h"
#include "gl/vertex_array.h"
#include "gl/query.h"
#include "gl/shader_source.h"
#include "tests/gpu/gl_fixture.h"

using namespace csm;

namespace {

// Full-screen triangles into a 1024 x 1024 target (draws, not dispatches: a software driver
// runs a dispatch before glDispatchCompute returns, outside any query, but rasterises draws
// after it).
class Painter {
 public:
  Painter() : color_(gl::Texture::create2D(GL_RGBA8, 1024, 1024)) {
    std::string log;
    program_ = gl::buildProgram(
        "solid",
        {{GL_VERTEX_SHADER, "test/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "test/solid.frag"}}, {},
        &log);
    INFO(log);
    REQUIRE(program_);
    program_->setUniform("color", glm::vec4(0.2f, 0.4f, 0.6f, 1.0f));
    fb_.attach(GL_COLOR_ATTACHMENT0, color_).setDrawBuffers({GL_COLOR_ATTACHMENT0});
    REQUIRE(fb_.checkComplete());
    // llvmpipe's first timer query in a process reads hours (its clock's start is not set
    // until then): one thrown away.
    gl::Query warmUp;
    warmUp.begin();
    draw(1);
    warmUp.end();
    (void)warmUp.result();
  }
  void draw(int triangles) {
    fb_.bind();
    glViewport(0, 0, 1024, 1024);
    program_->use();
    empty_.bind();
    for (int i = 0; i < triangles; ++i) glDrawArrays(GL_TRIANGLES, 0, 3);
    gl::VertexArray::unbind();
    gl::Framebuffer::bindDefault();
  }

 private:
  std::optional<gl::Program> program_;
  gl::Texture color_;
  gl::Framebuffer fb_;
  gl::VertexArray empty_;
};

std::uint64_t timedDraws(Painter& painter, int draws) {
  glFinish();
  gl::Query query;
  query.begin();
  painter.draw(draws);
  query.end();
  const std::uint64_t ns = query.result();  // waits
  CHECK(query.resultAvailable());
  return ns;
}

}  // namespace

TEST_CASE("GL: a timer query measures the work between its ends", "[gl][query][quick]") {
  test::glContext();
  Painter painter;
  // The least of five of each: on a software renderer the query times the CPU's work, and a busy
  // machine can stop the thread during any one of them (it only ever adds time).
  std::uint64_t light = UINT64_MAX, heavy = UINT64_MAX;
  for (int i = 0; i < 5; ++i) {
    light = std::min(light, timedDraws(painter, 1));
    heavy = std::min(heavy, timedDraws(painter, 64));
  }
  INFO("1 draw " << light << " ns, 64 draws " << heavy << " ns (least of five)");
  // 64 times the pixels take longer: the query times the work, not a constant or garbage.
  CHECK(heavy > 0);
  CHECK(heavy > light);
  CHECK(heavy < std::uint64_t(60e9));
  CHECK(gl::checkErrors("timer query"));
}

TEST_CASE("GL: StageTimer averages per named stage", "[gl][query][quick]") {
  test::glContext();
  Painter painter;
  gl::StageTimer timer(3);
  const int frames = 10;
  for (int f = 0; f < frames; ++f) {
    timer.beginFrame();  // collects finished results, never waits
    timer.begin("first");
    painter.draw(32);
    timer.begin("second");  // ends "first"
    painter.draw(1);
    timer.end();
  }
  timer.resolveNow();

  std::vector<gl::StageTimer::Stats> stats = timer.stats();
  REQUIRE(stats.size() == 2);
  CHECK(stats[0].name == "first");
  CHECK(stats[1].name == "second");
  for (const auto& s : stats) {
    CHECK(s.samples == std::size_t(frames));
    CHECK(s.meanMs < 60e3);
  }
  // Each stage is its own: 32 times the pixels take longer on average.
  INFO("first " << stats[0].meanMs << " ms, second " << stats[1].meanMs << " ms");
  CHECK(stats[0].meanMs > 0.0);
  CHECK(stats[0].meanMs > stats[1].meanMs);
  CHECK(timer.meanMs("first") == stats[0].meanMs);
  CHECK(timer.meanMs("unknown") == 0.0);

  timer.reset();
  CHECK(timer.stats().empty());
  CHECK(gl::checkErrors("stage timer"));
}
