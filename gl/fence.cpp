#include "gl/fence.h"

#include <atomic>
#include <utility>

#include "gl/debug.h"

namespace csm::gl {
namespace {

std::atomic<std::uint64_t> gBytes{0}, gReads{0}, gWaits{0};

}  // namespace

Fence::~Fence() {
  if (sync_) glDeleteSync(sync_);
}

Fence::Fence(Fence&& other) noexcept : sync_(std::exchange(other.sync_, nullptr)) {}

Fence& Fence::operator=(Fence&& other) noexcept {
  if (this != &other) {
    if (sync_) glDeleteSync(sync_);
    sync_ = std::exchange(other.sync_, nullptr);
  }
  return *this;
}

Fence Fence::insert() {
  Fence f;
  f.sync_ = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
  glFlush();
  maybeCheckErrors("Fence::insert");
  return f;
}

bool Fence::passed() const {
  if (!sync_) return true;
  const GLenum r = glClientWaitSync(sync_, 0, 0);
  return r == GL_ALREADY_SIGNALED || r == GL_CONDITION_SATISFIED;
}

bool Fence::wait(std::uint64_t timeoutNs) const {
  if (passed()) return true;
  countBlockingWait();
  const GLenum r = glClientWaitSync(sync_, GL_SYNC_FLUSH_COMMANDS_BIT, timeoutNs);
  return r == GL_ALREADY_SIGNALED || r == GL_CONDITION_SATISFIED;
}

void Fence::waitUncounted() const {
  if (!passed()) glClientWaitSync(sync_, GL_SYNC_FLUSH_COMMANDS_BIT, ~std::uint64_t(0));
}

void Fence::waitOnGpu() const {
  if (sync_) glWaitSync(sync_, 0, GL_TIMEOUT_IGNORED);
}

ReadbackStats readbackStats() {
  return {gBytes.load(), gReads.load(), gWaits.load()};
}

void resetReadbackStats() {
  gBytes = 0;
  gReads = 0;
  gWaits = 0;
}

void countReadback(std::uint64_t bytes) {
  gBytes += bytes;
  ++gReads;
}

void countBlockingWait() {
  ++gWaits;
}

}  // namespace csm::gl
