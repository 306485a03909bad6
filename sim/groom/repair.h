// The flaws of real grooms, repaired and counted, never silent: strands with a coordinate that
// is not a number, strands with fewer than two distinct points or shorter than the scene can
// resolve are dropped; points that repeat the one before (or nearly, closer than the scene
// needs) are merged into it. Each reader repairs what is wrong whatever the units (the first
// pass); the scene repairs again in metres once the groom is fitted to the head (the second),
// sim/groom/scene_groom.h's fitFileGroom.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "sim/core/groom.h"

namespace csm::io {

// What a repair did; added up over both passes.
struct GroomRepair {
  size_t droppedStrands = 0;  // strands removed
  size_t mergedPoints = 0;    // points removed into their neighbour
  // The first few repairs, one line each ("t.tfx: byte 248: strand 1 dropped: ..."), for the log
  // and the panel; the counts above hold all of them.
  std::vector<std::string> notes;
  static constexpr size_t kMaxNotes = 8;

  void add(const GroomRepair& other);
  bool empty() const { return droppedStrands == 0 && mergedPoints == 0; }
  // "dropped 3 strands, merged 12 points", or "" when nothing was repaired.
  std::string summary() const;
};

struct RepairOptions {
  // Strands whose arc length is below this are dropped (0: only those without length).
  double minLength = 0.0;
  // A point this close to the one kept before it is merged into it (0: only equal points).
  // A strand's tip is kept where it is: the point before it goes instead.
  double mergeDistance = 0.0;
  // Where coordinate `axis` (0 x, 1 y, 2 z) of point i (an index into Groom::points) lies in
  // the file, for the notes: "byte 248", "line 12". Empty: notes name the strand only.
  std::function<std::string(size_t point, int axis)> where;
  // Prefix of every note: the file's name.
  std::string name;
  // Strand s's number in the notes (the file's, when strands were dropped before); empty: s.
  std::vector<size_t> fileStrand;
};

// Repairs `groom` in place (per-strand colour and thickness follow their strands) and says
// what it did. Strands are numbered in notes as options.fileStrand says, else as they were in
// `groom` before the repair.
GroomRepair repairGroom(Groom& groom, const RepairOptions& options);

}  // namespace csm::io
