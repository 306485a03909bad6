// libFuzzer target: bytes as a TressFX file (sim/groom/tressfx.h), and what a preset does with a
// groom it accepts (fuzz_groom.h).
#include <cstddef>
#include <cstdint>
#include <span>

#include "sim/groom/tressfx.h"
#include "tests/fuzz/fuzz_groom.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::span<const std::byte> bytes(reinterpret_cast<const std::byte*>(data), size);
  const csm::io::GroomReadResult r = csm::io::readTressFx(bytes, "fuzz.tfx");
  if (!r.groom) {
    if (r.error.empty()) csm::fuzz::fail("readTressFx failed without a message");
    return 0;
  }
  // The header's version float (byte 0, not checked by the reader) picks the head and the fit.
  csm::fuzz::fitAsPreset(*r.groom, "fuzz.tfx", unsigned(data[0]));
  return 0;
}
