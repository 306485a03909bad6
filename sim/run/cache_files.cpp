#include "sim/run/cache_files.h"

#include <cstdio>
#include <cstring>
#include <span>
#include <vector>

#include "sim/base/file_io.h"
#include "sim/base/fnv.h"
#include "sim/base/state_bytes.h"

namespace csm::cache {
namespace {

constexpr char kFrameMagic[8] = {'c', 's', 'm', 'f', 'r', 'a', 'm', 'e'};
constexpr char kStateMagic[8] = {'c', 's', 'm', 's', 't', 'a', 't', 'e'};
constexpr size_t kHashAt = 96;
// A resume state's header: magic, version, 0, then the hash of the rest.
constexpr size_t kStateHashAt = 16;
// Larger than any scene the solvers take (kMaxParticles of 16 floats and more a particle).
constexpr uint64_t kMaxStateBytes = uint64_t(16) << 30;

// The file's hash, its hash field (8 bytes at `skipAt`) read as 0.
uint64_t fileHash(std::span<const std::byte> bytes, size_t skipAt) {
  const uint64_t zero = 0;
  uint64_t h = fnv1a(bytes.data(), skipAt);
  h = fnv1a(&zero, sizeof zero, h);
  return fnv1a(bytes.data() + skipAt + 8, bytes.size() - skipAt - 8, h);
}

void putPose(StateWriter& w, const Pose& p) {
  w.put(p.rotation.w);
  w.put(p.rotation.x);
  w.put(p.rotation.y);
  w.put(p.rotation.z);
  w.put(p.translation);
}

bool getPose(StateReader& r, Pose& p) {
  return r.get(p.rotation.w) && r.get(p.rotation.x) && r.get(p.rotation.y) && r.get(p.rotation.z) &&
         r.get(p.translation);
}

// The header both files start with; the hash filled once the rest is written.
void putHeader(StateWriter& w, const char (&magic)[8]) {
  for (char c : magic) w.put(c);
  w.put(kCacheVersion);
  w.put(uint32_t(0));
}

void sealHash(std::vector<std::byte>& bytes, size_t at) {
  const uint64_t h = fileHash(bytes, at);
  std::memcpy(bytes.data() + at, &h, sizeof h);
}

// The magic, the version and the hash at `hashAt` checked; false with the byte named.
bool checkHeader(const std::string& path, const std::vector<std::byte>& bytes,
                 const char (&magic)[8], size_t hashAt, const char* what, std::string* error) {
  auto fail = [&](uint64_t at, const std::string& message) {
    if (error) *error = io::detail::errorAt(path, at, message);
    return false;
  };
  if (bytes.size() < hashAt + 8)
    return fail(bytes.size(), "the file ends after " + std::to_string(bytes.size()) +
                                  " bytes, inside its header: not a whole " + what);
  if (std::memcmp(bytes.data(), magic, 8) != 0)
    return fail(0, std::string("not a ") + what + " of a csmhair cache");
  const uint32_t version = io::detail::loadLE<uint32_t>(bytes, 8);
  if (version != kCacheVersion)
    return fail(8, "a cache of format version " + std::to_string(version) +
                       "; this csmhair reads " + std::to_string(kCacheVersion) + ": bake it again");
  return true;
}

bool checkHash(const std::string& path, const std::vector<std::byte>& bytes, size_t hashAt,
               std::string* error) {
  if (io::detail::loadLE<uint64_t>(bytes, hashAt) == fileHash(bytes, hashAt)) return true;
  if (error)
    *error = io::detail::errorAt(path, hashAt,
                                 "the file's bytes do not match its hash: it was changed or "
                                 "damaged since it was written");
  return false;
}

}  // namespace

std::string frameName(long frame) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%05ld.bin", frame);
  return name;
}

bool writeFrame(const std::string& path, const FrameRecording::Shown& frame, std::string* error) {
  std::vector<std::byte> bytes;
  StateWriter w(bytes);
  putHeader(w, kFrameMagic);
  w.put(int64_t(frame.frame));
  w.put(frame.time);
  putPose(w, frame.head);
  w.put(uint64_t(frame.positions.size()));
  w.put(uint64_t(0));  // the hash
  for (const glm::vec3& p : frame.positions) w.put(p);
  sealHash(bytes, kHashAt);
  return io::detail::writeFileAtomically(path, bytes, error);
}

bool readFrame(const std::string& path, long number, size_t particles, FrameRecording::Shown& frame,
               std::string* error) {
  const std::optional<std::vector<std::byte>> read =
      io::detail::readFileBytes(path, 2 * frameBytes(particles) + 4096, error);
  if (!read) return false;
  const std::vector<std::byte>& bytes = *read;
  if (!checkHeader(path, bytes, kFrameMagic, kHashAt, "frame", error)) return false;
  const uint64_t n = io::detail::loadLE<uint64_t>(bytes, 88);
  if (n != particles) {
    if (error)
      *error =
          io::detail::errorAt(path, 88,
                              "a frame of " + std::to_string(n) +
                                  " particles; the cache's groom has " + std::to_string(particles));
    return false;
  }
  if (bytes.size() != frameBytes(particles)) {
    if (error)
      *error = io::detail::errorAt(path, bytes.size(),
                                   "the file ends after " + std::to_string(bytes.size()) +
                                       " of its " + std::to_string(frameBytes(particles)) +
                                       " bytes: a truncated frame");
    return false;
  }
  if (!checkHash(path, bytes, kHashAt, error)) return false;
  frame.frame = long(io::detail::loadLE<int64_t>(bytes, 16));
  if (frame.frame != number) {
    if (error)
      *error = io::detail::errorAt(path, 16,
                                   "the file of frame " + std::to_string(frame.frame) +
                                       " in the place of frame " + std::to_string(number));
    return false;
  }
  frame.time = io::detail::loadLE<double>(bytes, 24);
  frame.head.rotation =
      glm::dquat(io::detail::loadLE<double>(bytes, 32), io::detail::loadLE<double>(bytes, 40),
                 io::detail::loadLE<double>(bytes, 48), io::detail::loadLE<double>(bytes, 56));
  frame.head.translation =
      glm::dvec3(io::detail::loadLE<double>(bytes, 64), io::detail::loadLE<double>(bytes, 72),
                 io::detail::loadLE<double>(bytes, 80));
  frame.positions.resize(particles);
  if (particles > 0)
    std::memcpy(frame.positions.data(), bytes.data() + kFrameHeaderBytes, 12 * particles);
  return true;
}

bool writeState(const std::string& path, const SimulationState& state, std::string* error) {
  std::vector<std::byte> bytes;
  StateWriter w(bytes);
  putHeader(w, kStateMagic);
  w.put(uint64_t(0));  // the hash
  w.put(int64_t(state.frame));
  w.put(state.time);
  w.put(int64_t(state.carried));
  putPose(w, state.userPose);
  putPose(w, state.lastUserPose);
  putPose(w, state.lastPose);
  w.putVector(state.solver.bytes);
  sealHash(bytes, kStateHashAt);
  return io::detail::writeFileAtomically(path, bytes, error);
}

bool readState(const std::string& path, SimulationState& state, std::string* error) {
  const std::optional<std::vector<std::byte>> read =
      io::detail::readFileBytes(path, kMaxStateBytes, error);
  if (!read) return false;
  const std::vector<std::byte>& bytes = *read;
  if (!checkHeader(path, bytes, kStateMagic, kStateHashAt, "resume state", error) ||
      !checkHash(path, bytes, kStateHashAt, error))
    return false;
  const std::vector<std::byte> rest(bytes.begin() + kStateHashAt + 8, bytes.end());
  StateReader r(rest);
  int64_t frame = 0, carried = 0;
  const bool ok = r.get(frame) && r.get(state.time) && r.get(carried) &&
                  getPose(r, state.userPose) && getPose(r, state.lastUserPose) &&
                  getPose(r, state.lastPose) && r.getVector(state.solver.bytes) && r.done(nullptr);
  if (!ok) {
    if (error) *error = path + ": a resume state of another layout (another build of csmhair?)";
    return false;
  }
  state.frame = long(frame);
  state.carried = long(carried);
  return true;
}

}  // namespace csm::cache
