// A shot cache's frame and resume-state files (sim/run/cache_files.h): written and read back to
// the bit, and every damage a farm's disk or a stopped write can do refused with the byte named.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include <catch2/catch.hpp>

#include "sim/run/cache_files.h"
#include "sim/run/grown_scene.h"
#include "sim/run/simulation.h"
#include "sim/solver/cpu_solver.h"
#include "test_scenes.h"

namespace csm {
namespace {

namespace fs = std::filesystem;

struct TempDir {
  fs::path path = fs::temp_directory_path() / ("csm_cache_files_" + std::to_string(::getpid()));
  TempDir() { fs::create_directories(path); }
  ~TempDir() { fs::remove_all(path); }
  std::string operator/(const char* name) const { return (path / name).string(); }
};

FrameRecording::Shown aFrame(size_t particles) {
  FrameRecording::Shown f;
  f.frame = 31;
  f.time = 31.0 / 30.0;
  f.head = rotationAbout(glm::dvec3(0.0, 1.6, 0.0), glm::dvec3(1.0, 0.0, 0.0), 7.5);
  f.head.translation += glm::dvec3(0.25, 0.0, -1.5);
  for (size_t i = 0; i < particles; ++i)
    f.positions.push_back(
        glm::vec3(0.001f * float(i), 1.6f - 0.01f * float(i), 0.1f / float(i + 1)));
  return f;
}

void overwriteByte(const std::string& path, uint64_t at, char value) {
  std::fstream f(path, std::ios::in | std::ios::out | std::ios::binary);
  f.seekp(std::streamoff(at));
  f.put(value);
}

}  // namespace

TEST_CASE(
    "Cache frames: read back to the bit, and truncated, changed, of another version or groom "
    "refused with the byte",
    "[cache][quick]") {
  TempDir dir;
  const std::string path = dir / "frame_00031.bin";
  const FrameRecording::Shown written = aFrame(100);
  std::string error;
  REQUIRE(cache::writeFrame(path, written, &error));
  CHECK(fs::file_size(path) == cache::frameBytes(100));
  CHECK(cache::frameBytes(100) == 104 + 1200);

  FrameRecording::Shown read;
  REQUIRE(cache::readFrame(path, 31, 100, read, &error));
  CHECK(read.frame == 31);
  CHECK(read.time == written.time);
  CHECK(read.head.rotation == written.head.rotation);
  CHECK(read.head.translation == written.head.translation);
  REQUIRE(read.positions.size() == 100);
  CHECK(std::memcmp(read.positions.data(), written.positions.data(), 1200) == 0);

  SECTION("another groom's particle count") {
    CHECK_FALSE(cache::readFrame(path, 31, 99, read, &error));
    CHECK_THAT(error,
               Catch::Contains("byte 88: a frame of 100 particles; the cache's groom has 99"));
  }
  SECTION("truncated") {
    fs::resize_file(path, 1000);
    CHECK_FALSE(cache::readFrame(path, 31, 100, read, &error));
    CHECK_THAT(error, Catch::Contains("byte 1000: the file ends after 1000 of its 1304 bytes"));
    fs::resize_file(path, 50);
    CHECK_FALSE(cache::readFrame(path, 31, 100, read, &error));
    CHECK_THAT(error, Catch::Contains("inside its header"));
  }
  SECTION("a changed byte in the positions") {
    overwriteByte(path, 500, 0x7f);
    CHECK_FALSE(cache::readFrame(path, 31, 100, read, &error));
    CHECK_THAT(error, Catch::Contains("byte 96: the file's bytes do not match its hash"));
  }
  SECTION("another version") {
    overwriteByte(path, 8, 9);
    CHECK_FALSE(cache::readFrame(path, 31, 100, read, &error));
    CHECK_THAT(error, Catch::Contains("byte 8: a cache of format version 9; this csmhair reads 1"));
  }
  SECTION("not a frame") {
    overwriteByte(path, 0, 'X');
    CHECK_FALSE(cache::readFrame(path, 31, 100, read, &error));
    CHECK_THAT(error, Catch::Contains("byte 0: not a frame of a csmhair cache"));
  }
  SECTION("another frame's file") {
    CHECK_FALSE(cache::readFrame(path, 32, 100, read, &error));
    CHECK_THAT(error, Catch::Contains("byte 16: the file of frame 31 in the place of frame 32"));
  }
  SECTION("missing") {
    CHECK_FALSE(cache::readFrame(dir / "frame_00032.bin", 32, 100, read, &error));
    CHECK_THAT(error, Catch::Contains("frame_00032.bin: not a readable file"));
  }
}

TEST_CASE("Cache resume state: a simulation restored from it steps on as the one that wrote it",
          "[cache][quick]") {
  TempDir dir;
  Config c = test::smallScene(20);
  c.head.motion = HeadMotion::Shake;
  auto make = [&] {
    auto sim = std::make_unique<Simulation>(std::make_unique<CpuSolver>());
    std::string error;
    REQUIRE(sim->load(c, "", &error));
    return sim;
  };
  std::unique_ptr<Simulation> a = make(), b = make();
  for (int f = 0; f < 7; ++f) a->stepFrame();
  SimulationState saved;
  a->save(saved);
  std::string error;
  REQUIRE(cache::writeState(dir / "resume.state", saved, &error));

  SimulationState read;
  REQUIRE(cache::readState(dir / "resume.state", read, &error));
  CHECK(read.frame == 7);
  CHECK(read.time == saved.time);
  CHECK(read.lastPose.rotation == saved.lastPose.rotation);
  CHECK(read.solver.bytes == saved.solver.bytes);
  read.generation = b->generation();
  read.config = b->config();
  REQUIRE(b->restore(read, &error));
  for (int f = 0; f < 5; ++f) {
    a->stepFrame();
    b->stepFrame();
  }
  std::vector<glm::vec4> xa, xb;
  a->readPositions(xa);
  b->readPositions(xb);
  REQUIRE(xa.size() == xb.size());
  CHECK(std::memcmp(xa.data(), xb.data(), xa.size() * sizeof(glm::vec4)) == 0);

  // Damaged: refused, not restored.
  overwriteByte(dir / "resume.state", 200, 0x55);
  CHECK_FALSE(cache::readState(dir / "resume.state", read, &error));
  CHECK_THAT(error, Catch::Contains("do not match its hash"));
}

TEST_CASE("Cache: the groom's hash tells grooms apart and is the same for the same one",
          "[cache][quick]") {
  const Config c = test::smallScene(20);
  GrownScene one, two, other;
  std::string error;
  REQUIRE(growScene(c, "", nullptr, {}, one, &error));
  REQUIRE(growScene(c, "", one.head.get(), {}, two, &error));
  Config fewer = c;
  fewer.hairstyle.strands = 19;
  REQUIRE(growScene(fewer, "", one.head.get(), {}, other, &error));
  CHECK(groomHash(one) == groomHash(two));
  CHECK(groomHash(one) != groomHash(other));
}

}  // namespace csm
