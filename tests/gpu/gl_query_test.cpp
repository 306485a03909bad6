// Timer queries and the per-stage timer.
#include <vector>

#include "gl/buffer.h"
#include "gl/query.h"
#include "gl/shader_source.h"
#include "tests/gpu/gl_fixture.h"

using namespace csm;

namespace {

void work(gl::Program& program, gl::Buffer& buffer, GLuint count) {
  buffer.bindBase(GL_SHADER_STORAGE_BUFFER, 0);
  program.setUniform("count", count);
  program.dispatch(gl::Program::groupsFor(count, 64));
  gl::memoryBarrier(gl::Barrier::Storage);
}

}  // namespace

TEST_CASE("GL: a timer query returns a non-negative time", "[gl][query]") {
  test::glContext();
  auto program = gl::buildProgram("double", {{GL_COMPUTE_SHADER, "test/double.comp"}});
  REQUIRE(program);
  gl::Buffer buffer(std::vector<float>(1 << 16, 1.0f));

  gl::Query query;
  query.begin();
  work(*program, buffer, 1 << 16);
  query.end();
  std::uint64_t ns = query.result();  // waits
  CHECK(query.resultAvailable());
  // Unsigned, so "non-negative" means: a plausible value, not garbage.
  CHECK(ns < std::uint64_t(60e9));
  INFO("dispatch took " << ns << " ns");
  CHECK(gl::checkErrors("timer query"));
}

TEST_CASE("GL: StageTimer averages per named stage", "[gl][query]") {
  test::glContext();
  auto program = gl::buildProgram("double", {{GL_COMPUTE_SHADER, "test/double.comp"}});
  REQUIRE(program);
  gl::Buffer buffer(std::vector<float>(4096, 1.0f));

  gl::StageTimer timer(3);
  const int frames = 10;
  for (int f = 0; f < frames; ++f) {
    timer.beginFrame();  // collects finished results, never waits
    timer.begin("first");
    work(*program, buffer, 4096);
    timer.begin("second");  // ends "first"
    work(*program, buffer, 1024);
    timer.end();
  }
  timer.resolveNow();

  std::vector<gl::StageTimer::Stats> stats = timer.stats();
  REQUIRE(stats.size() == 2);
  CHECK(stats[0].name == "first");
  CHECK(stats[1].name == "second");
  for (const auto& s : stats) {
    CHECK(s.samples == std::size_t(frames));
    CHECK(s.meanMs >= 0.0);
    CHECK(s.meanMs < 60e3);
  }
  CHECK(timer.meanMs("first") == stats[0].meanMs);
  CHECK(timer.meanMs("unknown") == 0.0);

  timer.reset();
  CHECK(timer.stats().empty());
  CHECK(gl::checkErrors("stage timer"));
}
