#pragma once
#include <cstddef>
#include <cstdint>
#include <deque>
#include <string>
#include <string_view>
#include <vector>

#include "gl/gl.h"

namespace csm::gl {

// A query object; by default a GL_TIME_ELAPSED timer, whose result is GPU nanoseconds
// between begin() and end(). Only one query per target may be active at a time. Move-only.
class Query {
 public:
  explicit Query(NoCreateT) noexcept {}
  explicit Query(GLenum target = GL_TIME_ELAPSED);
  ~Query();
  Query(const Query&) = delete;
  Query& operator=(const Query&) = delete;
  Query(Query&& other) noexcept;
  Query& operator=(Query&& other) noexcept;

  static Query wrap(GLuint id, GLenum target);  // takes ownership
  GLuint release() noexcept;
  GLuint id() const { return id_; }
  GLenum target() const { return target_; }

  void begin();
  void end();
  // Does not wait.
  bool resultAvailable() const;
  // Waits for the GPU to reach end(). Nanoseconds for timer queries.
  std::uint64_t result() const;

 private:
  GLuint id_ = 0;
  GLenum target_ = GL_TIME_ELAPSED;
};

// GPU time per named stage (e.g. "predict", "shape match", "collide", "draw"), averaged
// over frames. Stages run one after another: begin("b") while "a" is open ends "a" first,
// because GL allows one active GL_TIME_ELAPSED query.
//
// Reading a query the frame it was issued would stall the CPU until the GPU catches up, so
// each stage keeps a ring of queries and collect() (called by beginFrame()) takes only the
// ones already finished: a frame's times arrive a few frames later. resolveNow() waits for
// all of them, for headless runs and benchmarks.
class StageTimer {
 public:
  struct Stats {
    std::string name;
    double meanMs = 0;  // over every collected sample since reset()
    double lastMs = 0;  // the most recent collected sample
    std::size_t samples = 0;
  };

  // `maxInFlight` queries per stage may wait for results; past that the oldest is waited
  // for (a stall, but bounded memory when nobody calls beginFrame()).
  explicit StageTimer(std::size_t maxInFlight = 8)
      : maxInFlight_(maxInFlight > 0 ? maxInFlight : 1) {}

  void beginFrame() { collect(); }
  void begin(std::string_view stage);
  void end();  // ends the open stage, if any

  // Takes the finished results without waiting.
  void collect();
  // Ends any open stage and waits for every pending result.
  void resolveNow();
  // Forgets every stage and sample.
  void reset();

  // 0 for an unknown stage or one with no samples yet.
  double meanMs(std::string_view stage) const;
  // In the order stages were first begun.
  std::vector<Stats> stats() const;

 private:
  struct Stage {
    std::string name;
    std::deque<Query> pending;  // issued, in order; results arrive in this order
    std::vector<Query> free;
    double totalNs = 0;
    double lastNs = 0;
    std::size_t samples = 0;
  };
  Stage* find(std::string_view name);
  const Stage* find(std::string_view name) const;
  static void take(Stage& stage);

  std::deque<Stage> stages_;  // a deque: growing it moves no Stage, so open_ stays valid
  Stage* open_ = nullptr;
  std::size_t maxInFlight_;
};

}  // namespace csm::gl
