// Plain values and arrays to and from a byte buffer, for the solvers' saved states
// (SavedState, sim/core/solver.h): memcpy'd in this process's own layout, read back only by it.
#pragma once

#include <cstddef>
#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

namespace csm {

class StateWriter {
 public:
  explicit StateWriter(std::vector<std::byte>& out) : out_(out) { out_.clear(); }
  template <class T>
  void put(const T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    append(&value, sizeof(T));
  }
  template <class T>
  void putVector(const std::vector<T>& values) {
    static_assert(std::is_trivially_copyable_v<T>);
    put(values.size());
    append(values.data(), values.size() * sizeof(T));
  }

 private:
  void append(const void* data, size_t n) {
    const size_t at = out_.size();
    out_.resize(at + n);
    if (n > 0) std::memcpy(out_.data() + at, data, n);
  }
  std::vector<std::byte>& out_;
};

class StateReader {
 public:
  explicit StateReader(const std::vector<std::byte>& in) : in_(in) {}
  template <class T>
  bool get(T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    return take(&value, sizeof(T));
  }
  // An array written by putVector, of exactly `count` values.
  template <class T>
  bool getVector(std::vector<T>& values, size_t count) {
    size_t n = 0;
    if (!get(n) || n != count || in_.size() - at_ < n * sizeof(T)) return false;
    values.resize(n);
    return take(values.data(), n * sizeof(T));
  }
  // An array written by putVector, of any length the bytes left hold.
  template <class T>
  bool getVector(std::vector<T>& values) {
    static_assert(std::is_trivially_copyable_v<T>);
    size_t n = 0;
    if (!get(n) || n > (in_.size() - at_) / sizeof(T)) return false;
    values.resize(n);
    return take(values.data(), n * sizeof(T));
  }
  // The count written first (put(size_t)), which must be `count`: "a saved state of 1200
  // particles; this scene has 1300".
  bool expectCount(size_t count, const char* what, std::string* error) {
    size_t saved = 0;
    if (!get(saved)) return fail(error, "a saved state too short to read");
    if (saved != count)
      return fail(error, "a saved state of " + std::to_string(saved) + " " + what +
                             "; this scene has " + std::to_string(count));
    return true;
  }
  bool done(std::string* error) {
    return at_ == in_.size() || fail(error, "a saved state of another layout");
  }

 private:
  bool take(void* data, size_t n) {
    if (in_.size() - at_ < n) return false;
    if (n > 0) std::memcpy(data, in_.data() + at_, n);
    at_ += n;
    return true;
  }
  static bool fail(std::string* error, const std::string& message) {
    if (error) *error = message;
    return false;
  }
  const std::vector<std::byte>& in_;
  size_t at_ = 0;
};

}  // namespace csm
