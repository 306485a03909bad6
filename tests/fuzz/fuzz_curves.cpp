// libFuzzer target: text as OBJ hair curves (sim/groom/obj_curves.h, what a groom .obj reads as),
// and what a preset does with a groom it accepts (fuzz_groom.h), roots found as for OBJ.
#include <cstddef>
#include <cstdint>
#include <span>

#include "sim/groom/obj_curves.h"
#include "tests/fuzz/fuzz_groom.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::span<const std::byte> bytes(reinterpret_cast<const std::byte*>(data), size);
  const csm::io::GroomReadResult r = csm::io::readObjCurves(bytes, "fuzz.obj");
  if (!r.groom) {
    if (r.error.empty()) csm::fuzz::fail("readObjCurves failed without a message");
    return 0;
  }
  if (r.rootsKnown) csm::fuzz::fail("OBJ curves do not say which end is the root");
  // The input's length picks the head and the fit: the text has no spare byte to spend.
  csm::fuzz::fitAsPreset(*r.groom, "fuzz.obj", unsigned(size), true);
  return 0;
}
