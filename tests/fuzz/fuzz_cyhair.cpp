// libFuzzer target: bytes as a cyHair file (sim/groom/cyhair.h), and what a preset does with a
// groom it accepts (fuzz_groom.h).
#include <cstddef>
#include <cstdint>
#include <span>

#include "sim/groom/cyhair.h"
#include "tests/fuzz/fuzz_groom.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::span<const std::byte> bytes(reinterpret_cast<const std::byte*>(data), size);
  const csm::io::GroomReadResult r = csm::io::readCyHair(bytes, "fuzz.hair");
  if (!r.groom) {
    if (r.error.empty()) csm::fuzz::fail("readCyHair failed without a message");
    return 0;
  }
  // The header's free text (byte 40) picks the head and the fit: the fuzzer can reach them all.
  csm::fuzz::fitAsPreset(*r.groom, "fuzz.hair", size > 40 ? unsigned(data[40]) : 0u);
  return 0;
}
