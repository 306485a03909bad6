#include "gl/query.h"

#include <utility>

#include "gl/debug.h"

namespace csm::gl {

Query::Query(GLenum target) : target_(target) {
  glGenQueries(1, &id_);
  maybeCheckErrors("Query::Query");
}

Query::~Query() {
  if (id_) glDeleteQueries(1, &id_);
}

Query::Query(Query&& other) noexcept : id_(std::exchange(other.id_, 0)), target_(other.target_) {}

Query& Query::operator=(Query&& other) noexcept {
  if (this != &other) {
    if (id_) glDeleteQueries(1, &id_);
    id_ = std::exchange(other.id_, 0);
    target_ = other.target_;
  }
  return *this;
}

Query Query::wrap(GLuint id, GLenum target) {
  Query q{NoCreate};
  q.id_ = id;
  q.target_ = target;
  return q;
}

GLuint Query::release() noexcept {
  return std::exchange(id_, 0);
}

void Query::begin() {
  glBeginQuery(target_, id_);
  maybeCheckErrors("Query::begin");
}

void Query::end() {
  glEndQuery(target_);
  maybeCheckErrors("Query::end");
}

bool Query::resultAvailable() const {
  GLuint available = GL_FALSE;
  glGetQueryObjectuiv(id_, GL_QUERY_RESULT_AVAILABLE, &available);
  return available == GL_TRUE;
}

std::uint64_t Query::result() const {
  GLuint64 value = 0;
  glGetQueryObjectui64v(id_, GL_QUERY_RESULT, &value);
  maybeCheckErrors("Query::result");
  return value;
}

StageTimer::Stage* StageTimer::find(std::string_view name) {
  for (Stage& s : stages_)
    if (s.name == name) return &s;
  return nullptr;
}

const StageTimer::Stage* StageTimer::find(std::string_view name) const {
  for (const Stage& s : stages_)
    if (s.name == name) return &s;
  return nullptr;
}

void StageTimer::take(Stage& stage) {
  Query q = std::move(stage.pending.front());
  stage.pending.pop_front();
  stage.lastNs = double(q.result());
  stage.totalNs += stage.lastNs;
  ++stage.samples;
  stage.free.push_back(std::move(q));
}

void StageTimer::begin(std::string_view name) {
  end();
  Stage* stage = find(name);
  if (!stage) {
    stage = &stages_.emplace_back();
    stage->name = std::string(name);
  }
  while (stage->pending.size() >= maxInFlight_) take(*stage);
  Query q{NoCreate};
  if (stage->free.empty()) {
    q = Query(GL_TIME_ELAPSED);
  } else {
    q = std::move(stage->free.back());
    stage->free.pop_back();
  }
  q.begin();
  stage->pending.push_back(std::move(q));
  open_ = stage;
}

void StageTimer::end() {
  if (!open_) return;
  open_->pending.back().end();
  open_ = nullptr;
}

void StageTimer::collect() {
  for (Stage& s : stages_) {
    // Results complete in issue order; the open query has no result yet.
    std::size_t ready = s.pending.size() - (&s == open_ ? 1 : 0);
    while (ready > 0 && s.pending.front().resultAvailable()) {
      take(s);
      --ready;
    }
  }
}

void StageTimer::resolveNow() {
  end();
  for (Stage& s : stages_)
    while (!s.pending.empty()) take(s);
}

void StageTimer::reset() {
  end();
  stages_.clear();
}

double StageTimer::meanMs(std::string_view name) const {
  const Stage* s = find(name);
  return s && s->samples ? s->totalNs / double(s->samples) * 1e-6 : 0.0;
}

std::vector<StageTimer::Stats> StageTimer::stats() const {
  std::vector<Stats> out;
  for (const Stage& s : stages_)
    out.push_back({s.name, s.samples ? s.totalNs / double(s.samples) * 1e-6 : 0.0, s.lastNs * 1e-6,
                   s.samples});
  return out;
}

}  // namespace csm::gl
