// The sampled-field cache (sim/head/field_cache.h): what it returns is bitwise what sampling
// returns, whether it was read, written or refused; a damaged entry is sampled again; the
// folder keeps a few entries a name; no folder, no cache.
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <glm/geometric.hpp>

#include "sim/head/distance_grid.h"
#include "sim/head/field_cache.h"

using namespace csm;
namespace fs = std::filesystem;

namespace {

double ball(const glm::dvec3& p) {
  return glm::length(p - glm::dvec3(0.01, 0.0, -0.02)) - 0.05;
}

const glm::dvec3 kLo(-0.08, -0.08, -0.1), kHi(0.08, 0.08, 0.06);

bool sameGrid(const DistanceGrid& a, const DistanceGrid& b) {
  return a.origin == b.origin && a.cell == b.cell && a.dims == b.dims &&
         a.nodes.size() == b.nodes.size() &&
         std::memcmp(a.nodes.data(), b.nodes.data(), a.nodes.size() * sizeof(glm::vec4)) == 0;
}

// CSM_CACHE_DIR set for one test case, a fresh folder under the system's temporary one.
struct CacheDir {
  fs::path dir = fs::temp_directory_path() / ("csm_field_cache_" + std::to_string(::getpid()));
  CacheDir() {
    fs::remove_all(dir);
    ::setenv("CSM_CACHE_DIR", dir.c_str(), 1);
  }
  ~CacheDir() {
    ::unsetenv("CSM_CACHE_DIR");
    fs::remove_all(dir);
  }
  std::vector<fs::path> entries() const {
    std::vector<fs::path> files;
    if (fs::exists(dir))
      for (const auto& e : fs::directory_iterator(dir)) files.push_back(e.path());
    return files;
  }
};

}  // namespace

TEST_CASE("field cache: written once, read after, bitwise the sampled field", "[head][quick]") {
  CacheDir cache;
  const DistanceGrid sampled = sampleDistance(ball, kLo, kHi, 0.004);
  FieldCacheResult result = FieldCacheResult::Off;
  const DistanceGrid first = cachedSampleDistance("ball", ball, kLo, kHi, 0.004, &result);
  CHECK(result == FieldCacheResult::Written);
  CHECK(sameGrid(first, sampled));
  REQUIRE(cache.entries().size() == 1);
  const DistanceGrid second = cachedSampleDistance("ball", ball, kLo, kHi, 0.004, &result);
  CHECK(result == FieldCacheResult::Read);
  CHECK(sameGrid(second, sampled));

  // Another cell is another entry; the first stays.
  const DistanceGrid finer = cachedSampleDistance("ball", ball, kLo, kHi, 0.003, &result);
  CHECK(result == FieldCacheResult::Written);
  CHECK(sameGrid(finer, sampleDistance(ball, kLo, kHi, 0.003)));
  CHECK(cache.entries().size() == 2);
  cachedSampleDistance("ball", ball, kLo, kHi, 0.004, &result);
  CHECK(result == FieldCacheResult::Read);
}

TEST_CASE("field cache: a damaged or truncated entry is sampled again and replaced",
          "[head][quick]") {
  CacheDir cache;
  const DistanceGrid sampled = sampleDistance(ball, kLo, kHi, 0.004);
  FieldCacheResult result = FieldCacheResult::Off;
  cachedSampleDistance("ball", ball, kLo, kHi, 0.004, &result);
  REQUIRE(cache.entries().size() == 1);
  const fs::path entry = cache.entries().front();
  const auto size = fs::file_size(entry);

  // One node's byte changed: the checksum refuses it.
  {
    std::fstream f(entry, std::ios::in | std::ios::out | std::ios::binary);
    f.seekg(std::streamoff(size - 100));
    char c = 0;
    f.read(&c, 1);
    c = char(c ^ 0x40);
    f.seekp(std::streamoff(size - 100));
    f.write(&c, 1);
  }
  DistanceGrid grid = cachedSampleDistance("ball", ball, kLo, kHi, 0.004, &result);
  CHECK(result == FieldCacheResult::Written);
  CHECK(sameGrid(grid, sampled));
  cachedSampleDistance("ball", ball, kLo, kHi, 0.004, &result);
  CHECK(result == FieldCacheResult::Read);

  // Cut short: its size refuses it.
  fs::resize_file(entry, size / 2);
  grid = cachedSampleDistance("ball", ball, kLo, kHi, 0.004, &result);
  CHECK(result == FieldCacheResult::Written);
  CHECK(sameGrid(grid, sampled));
  CHECK(fs::file_size(entry) == size);
}

TEST_CASE("field cache: a few entries a name kept, the newest", "[head][quick]") {
  CacheDir cache;
  FieldCacheResult result = FieldCacheResult::Off;
  for (double cell : {0.008, 0.007, 0.006, 0.005, 0.0045, 0.004}) {
    cachedSampleDistance("ball", ball, kLo, kHi, cell, &result);
    CHECK(result == FieldCacheResult::Written);
  }
  CHECK(cache.entries().size() == 4);
  cachedSampleDistance("ball", ball, kLo, kHi, 0.004, &result);
  CHECK(result == FieldCacheResult::Read);
  // Another name's entries are its own.
  cachedSampleDistance("other", ball, kLo, kHi, 0.008, &result);
  CHECK(result == FieldCacheResult::Written);
  CHECK(cache.entries().size() == 5);
}

TEST_CASE("field cache: none when CSM_CACHE_DIR is empty, sampled when unwritable",
          "[head][quick]") {
  CacheDir cache;
  const DistanceGrid sampled = sampleDistance(ball, kLo, kHi, 0.004);
  FieldCacheResult result = FieldCacheResult::Read;
  ::setenv("CSM_CACHE_DIR", "", 1);
  CHECK(fieldCacheDir().empty());
  CHECK(sameGrid(cachedSampleDistance("ball", ball, kLo, kHi, 0.004, &result), sampled));
  CHECK(result == FieldCacheResult::Off);

  // A folder that cannot be made (under a file): sampled, nothing written, no error.
  fs::create_directories(cache.dir);
  std::ofstream(cache.dir / "file") << "x";
  ::setenv("CSM_CACHE_DIR", (cache.dir / "file" / "sub").c_str(), 1);
  CHECK(sameGrid(cachedSampleDistance("ball", ball, kLo, kHi, 0.004, &result), sampled));
  CHECK(result == FieldCacheResult::Unwritable);
}
