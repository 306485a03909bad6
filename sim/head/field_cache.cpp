#include "sim/head/field_cache.h"

#include <sys/stat.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <span>
#include <system_error>
#include <vector>

#include "sim/base/file_io.h"

namespace csm {

namespace {

namespace fs = std::filesystem;

constexpr char kMagic[8] = {'C', 'S', 'M', 'F', 'I', 'E', 'L', 'D'};
constexpr uint32_t kVersion = 1;
constexpr size_t kKeepPerName = 4;  // entries of one name kept: 15 MB each for the mannequin

// What an entry is valid for: the program that wrote it, the box and the cell.
struct Key {
  uint64_t device = 0, inode = 0, size = 0;
  int64_t modifiedNs = 0;
  double lo[3] = {}, hi[3] = {}, cell = 0.0;
};

struct Header {
  char magic[8];
  uint32_t version;
  uint32_t reserved;
  Key key;
  float origin[3];
  float cell;
  int32_t dims[3];
  uint32_t reserved2;
  uint64_t nodes;
  uint64_t checksum;  // of the nodes' bytes
};

// FNV-1a over 64-bit words: 15 MB in a few milliseconds.
uint64_t checksum(std::span<const std::byte> bytes) {
  uint64_t h = 1469598103934665603ull;
  size_t i = 0;
  for (; i + 8 <= bytes.size(); i += 8) {
    uint64_t w;
    std::memcpy(&w, bytes.data() + i, 8);
    h = (h ^ w) * 1099511628211ull;
  }
  for (; i < bytes.size(); ++i) h = (h ^ uint64_t(bytes[i])) * 1099511628211ull;
  return h;
}

bool programKey(Key& key) {
  struct stat st {};
  if (::stat("/proc/self/exe", &st) != 0) return false;
  key.device = uint64_t(st.st_dev);
  key.inode = uint64_t(st.st_ino);
  key.size = uint64_t(st.st_size);
  key.modifiedNs = int64_t(st.st_mtim.tv_sec) * 1000000000 + int64_t(st.st_mtim.tv_nsec);
  return true;
}

std::string hex(uint64_t v) {
  static const char digits[] = "0123456789abcdef";
  std::string s(16, '0');
  for (int i = 15; i >= 0; --i, v >>= 4) s[size_t(i)] = digits[v & 15];
  return s;
}

bool read(const std::string& path, const Key& key, DistanceGrid& grid) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) return false;
  const uint64_t most = sizeof(Header) + (uint64_t(1) << 32);
  auto bytes = io::detail::readFileBytes(path, most, nullptr);
  if (!bytes || bytes->size() < sizeof(Header)) return false;
  Header h;
  std::memcpy(&h, bytes->data(), sizeof(Header));
  if (std::memcmp(h.magic, kMagic, sizeof(kMagic)) != 0 || h.version != kVersion ||
      std::memcmp(&h.key, &key, sizeof(Key)) != 0 || h.dims[0] < 2 || h.dims[1] < 2 ||
      h.dims[2] < 2 || h.nodes != uint64_t(h.dims[0]) * uint64_t(h.dims[1]) * uint64_t(h.dims[2]) ||
      bytes->size() != sizeof(Header) + h.nodes * sizeof(glm::vec4))
    return false;
  const std::span<const std::byte> payload(bytes->data() + sizeof(Header),
                                           h.nodes * sizeof(glm::vec4));
  if (checksum(payload) != h.checksum) return false;
  grid.origin = glm::vec3(h.origin[0], h.origin[1], h.origin[2]);
  grid.cell = h.cell;
  grid.dims = glm::ivec3(h.dims[0], h.dims[1], h.dims[2]);
  grid.nodes.resize(size_t(h.nodes));
  std::memcpy(grid.nodes.data(), payload.data(), payload.size());
  return true;
}

// Header and nodes in one file, written whole or not at all (io::detail::writeFileAtomically).
bool write(const std::string& path, const Key& key, const DistanceGrid& grid) {
  Header h{};
  std::memcpy(h.magic, kMagic, sizeof(kMagic));
  h.version = kVersion;
  h.key = key;
  for (int a = 0; a < 3; ++a) {
    h.origin[a] = grid.origin[a];
    h.dims[a] = grid.dims[a];
  }
  h.cell = grid.cell;
  h.nodes = grid.nodes.size();
  const size_t payload = grid.nodes.size() * sizeof(glm::vec4);
  std::vector<std::byte> bytes(sizeof(Header) + payload);
  std::memcpy(bytes.data() + sizeof(Header), grid.nodes.data(), payload);
  h.checksum = checksum(std::span<const std::byte>(bytes).subspan(sizeof(Header)));
  std::memcpy(bytes.data(), &h, sizeof(Header));
  return io::detail::writeFileAtomically(path, bytes, nullptr);
}

// Keeps the newest kKeepPerName entries named `<name>-*.field`.
void prune(const std::string& dir, std::string_view name) {
  std::error_code ec;
  std::vector<std::pair<fs::file_time_type, fs::path>> entries;
  const std::string prefix = std::string(name) + "-";
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    const std::string file = e.path().filename().string();
    if (file.rfind(prefix, 0) == 0 && e.path().extension() == ".field")
      entries.emplace_back(e.last_write_time(ec), e.path());
  }
  if (entries.size() <= kKeepPerName) return;
  std::sort(entries.begin(), entries.end(),
            [](const auto& a, const auto& b) { return a.first > b.first; });
  for (size_t i = kKeepPerName; i < entries.size(); ++i) fs::remove(entries[i].second, ec);
}

}  // namespace

std::string fieldCacheDir() {
  if (const char* dir = std::getenv("CSM_CACHE_DIR")) return dir;
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
    return (fs::path(xdg) / "csmhair").string();
  if (const char* home = std::getenv("HOME"); home && *home)
    return (fs::path(home) / ".cache" / "csmhair").string();
  return "";
}

DistanceGrid cachedSampleDistance(std::string_view name, const DistanceFunction& f,
                                  const glm::dvec3& lo, const glm::dvec3& hi, double cell,
                                  FieldCacheResult* result) {
  FieldCacheResult outcome = FieldCacheResult::Off;
  const std::string dir = fieldCacheDir();
  Key key;
  for (int a = 0; a < 3; ++a) {
    key.lo[a] = lo[a];
    key.hi[a] = hi[a];
  }
  key.cell = cell;
  DistanceGrid grid;
  if (!dir.empty() && programKey(key)) {
    const std::span<const std::byte> keyBytes(reinterpret_cast<const std::byte*>(&key),
                                              sizeof(key));
    const std::string path =
        (fs::path(dir) / (std::string(name) + "-" + hex(checksum(keyBytes)) + ".field")).string();
    if (read(path, key, grid)) {
      outcome = FieldCacheResult::Read;
    } else {
      grid = sampleDistance(f, lo, hi, cell);
      std::error_code ec;
      fs::create_directories(dir, ec);
      outcome = write(path, key, grid) ? FieldCacheResult::Written : FieldCacheResult::Unwritable;
      if (outcome == FieldCacheResult::Written) prune(dir, name);
    }
  } else {
    grid = sampleDistance(f, lo, hi, cell);
  }
  if (result) *result = outcome;
  return grid;
}

}  // namespace csm
