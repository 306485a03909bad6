// A rolling history of floats for ImGui::PlotLines: the Stats panel's frame times and
// strains.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

namespace csm {

// A fixed number of the latest values, oldest first when read from offset().
class History {
 public:
  explicit History(std::size_t capacity) : values_(capacity, 0.0f) {}
  void push(float v) {
    values_[next_] = v;
    next_ = (next_ + 1) % values_.size();
    count_ = std::min(count_ + 1, values_.size());
  }
  void clear() {
    std::fill(values_.begin(), values_.end(), 0.0f);
    next_ = count_ = 0;
  }
  // PlotLines(values(), size(), offset()) draws oldest to newest.
  const float* values() const { return values_.data(); }
  int size() const { return int(count_ < values_.size() ? count_ : values_.size()); }
  int offset() const { return count_ < values_.size() ? 0 : int(next_); }
  bool empty() const { return count_ == 0; }
  float latest() const {
    return empty() ? 0.0f : values_[(next_ + values_.size() - 1) % values_.size()];
  }
  float max() const {
    return empty() ? 0.0f : *std::max_element(values_.begin(), values_.begin() + size());
  }
  float mean() const {
    float s = 0.0f;
    for (int i = 0; i < size(); ++i) s += values_[i];
    return empty() ? 0.0f : s / float(size());
  }

 private:
  std::vector<float> values_;
  std::size_t next_ = 0, count_ = 0;
};

}  // namespace csm
