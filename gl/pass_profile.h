// Where a GPU frame goes, pass by pass, for profiling (CSM_PASS_PROFILE=1 in the environment):
// every compute dispatch (Program::dispatchItems and dispatchIndirect: the solver's passes and
// the renderer's) waits for the GPU before and after it (glFinish), and its wall time adds to
// its program's row; `csmhair --headless` prints the table as it ends. The waits make the frame
// slower and each pass's time its own (llvmpipe runs a dispatch inside the call anyway). Off, it
// costs one branch a dispatch.
#pragma once

#include <string>

namespace csm::gl::pass_profile {

bool enabled();
// Runs `dispatch`: profiling, between two waits, its time added to `path`'s row.
template <class F>
void run(const std::string& path, F&& dispatch);
// Forgets what was timed (the set-up before the frames).
void clear();
// The table, ms a frame over `frames` frames and runs a frame, slowest first; empty when
// nothing was timed.
std::string table(long frames);

namespace detail {
void finish();
double nowMs();
void add(const std::string& path, double ms);
}  // namespace detail

template <class F>
void run(const std::string& path, F&& dispatch) {
  if (!enabled()) {
    dispatch();
    return;
  }
  detail::finish();
  const double t0 = detail::nowMs();
  dispatch();
  detail::finish();
  detail::add(path, detail::nowMs() - t0);
}

}  // namespace csm::gl::pass_profile
