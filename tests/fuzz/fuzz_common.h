// What every fuzz target shares: a failed check aborts (libFuzzer keeps the input), and the
// simulation's loops run on the fuzzer's thread (CSM_THREADS=1): a thread pool would make an
// execution's time depend on the machine's other load, and the fuzzer runs one per core.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <string>

namespace csm::fuzz {

[[noreturn]] inline void fail(const std::string& what) {
  std::fprintf(stderr, "fuzz target: %s\n", what.c_str());
  std::abort();
}

}  // namespace csm::fuzz

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  setenv("CSM_THREADS", "1", 1);
  return 0;
}
