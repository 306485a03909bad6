#include "app/triple_buffer.h"

namespace csm {

int TripleBuffer::write(unsigned source, std::size_t bytes) {
  int s = -1;
  gl::Fence readDone;
  {
    std::lock_guard lock(mutex_);
    for (int i = 0; i < int(slots_.size()); ++i)
      if (i != latest_ && i != held_) {
        s = i;
        break;
      }
    readDone = std::move(slots_[s].read);
  }
  // The window's draws from this buffer, if any, are done (usually long since). Neither side
  // touches a slot that is neither latest nor held but the writer.
  readDone.wait();
  readDone = gl::Fence();
  Slot& slot = slots_[s];
  if (slot.buffer.id() == 0) slot.buffer = gl::Buffer();
  if (std::size_t(slot.buffer.size()) != bytes)
    slot.buffer.setData(GLsizeiptr(bytes), nullptr, gl::BufferUsage::DynamicCopy);
  // The solver wrote the positions from compute shaders.
  gl::memoryBarrier(gl::Barrier::BufferUpdate);
  gl::copyBuffer(source, slot.buffer.id(), GLsizeiptr(bytes));
  slot.written = gl::Fence::insert();
  return s;
}

void TripleBuffer::publish(int slot) {
  std::lock_guard lock(mutex_);
  latest_ = slot;
}

void TripleBuffer::hold(int slot) {
  std::lock_guard lock(mutex_);
  if (slot < 0 || slot == held_) return;
  held_ = slot;
  slots_[held_].written.waitOnGpu();
}

void TripleBuffer::drawn() {
  std::lock_guard lock(mutex_);
  if (held_ >= 0) slots_[held_].read = gl::Fence::insert();
}

unsigned TripleBuffer::buffer(int slot) const {
  std::lock_guard lock(mutex_);
  return slots_[slot].buffer.id();
}

void TripleBuffer::release() {
  std::lock_guard lock(mutex_);
  for (Slot& s : slots_) s = Slot{};
}

}  // namespace csm
