// How large the strand-contact buffers that grow with the hair's density are, and may be on
// this device: the grid's entries and the candidate pair list (with its sides and each frame's
// lists), grown a quarter over what a search needed, never past what one buffer and one view of
// it hold (the device's buffer textures, limitStorage in tests). No GL: the ContactSearch
// (sim/gpu/contact_search.h) reallocates what this says.
#pragma once

#include <cstdint>

namespace csm::gpu {

class ContactCapacity {
 public:
  // The device's buffer textures: the most texels one view holds, and where a view of a
  // buffer's range may start (bytes).
  void setDevice(uint64_t textureTexels, uint64_t viewAlignment);
  // Caps each growing buffer at `bytes` (tests; UINT64_MAX: the device's own limit).
  void limitStorage(uint64_t bytes) { bufferBytes_ = bytes; }
  // Caps the growing buffers together at `bytes` (collision.contact_memory_mb): a quarter for
  // the entries (16 bytes each), the rest for the pairs (64 bytes each: the pair list, its
  // sides and both frames' lists), from the next reserve on.
  void setBudget(uint64_t bytes) { budgetBytes_ = bytes; }
  // Caps the texels of the first view of the sides and the lists (tests).
  void limitListSplit(uint64_t texels) { splitTexels_ = texels; }

  // Where the second view of the sides and of the lists starts: as many RG32UI texels as a view
  // holds, down to where a view may start.
  uint32_t listSplit() const;
  // The most entries and candidate pairs the buffers may take.
  uint64_t entryLimit() const;
  uint64_t pairLimit() const;

  uint32_t entries() const { return entries_; }
  uint32_t pairs() const { return pairs_; }
  // Both 0 (a reset: reserveFor sizes them).
  void clear() { entries_ = pairs_ = 0; }
  // Room for `needed` entries (pairs): a quarter more, so that a growing tangle does not
  // reallocate every frame, within the limit. True when that is more than there is (the buffers
  // must be made again at the new capacity).
  bool growEntries(uint64_t needed);
  bool growPairs(uint64_t needed);
  // Whether the sides and the lists run past their first view (the passes' second build).
  bool splitViews() const { return 2 * uint64_t(pairs_) > listSplit(); }

 private:
  uint64_t budgetEntries() const;  // the entries and pairs setBudget allows
  uint64_t budgetPairs() const;
  uint32_t entries_ = 0;               // grid entries the entry buffer holds
  uint32_t pairs_ = 0;                 // candidate pairs the pair list holds
  uint64_t bufferBytes_ = UINT64_MAX;  // the most one growing buffer may take
  uint64_t budgetBytes_ = UINT64_MAX;  // the most the growing buffers take together
  uint64_t textureTexels_ = 0;         // the most texels one buffer texture holds
  uint64_t viewAlignment_ = 1;         // bytes: where a view of a buffer's range may start
  uint64_t splitTexels_ = UINT64_MAX;  // limitListSplit's cap
};

}  // namespace csm::gpu
