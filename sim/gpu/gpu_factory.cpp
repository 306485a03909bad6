// makeSolver("gpu") lands here (sim/simulation.cpp): the GPU solver, if the current GL context
// can run it.
#include <memory>
#include <string>

#include "render/gl/caps.h"
#include "sim/gpu/gpu_solver.h"

namespace csm {

std::unique_ptr<Solver> makeGpuSolver(std::string* error) {
  // Without a current context GL calls go to the dispatcher's no-op stubs: GL_VERSION is null.
  if (glGetString(GL_VERSION) == nullptr) {
    if (error)
      *error =
          "the GPU solver needs a current OpenGL 4.3 context and none is current "
          "(headless runs make one through EGL; or use --solver cpu)";
    return nullptr;
  }
  const gl::Caps caps = gl::queryCaps();
  if (caps.major * 10 + caps.minor < 43) {
    if (error)
      *error = "the GPU solver needs OpenGL 4.3 compute shaders; the context is " + caps.version +
               " on " + caps.renderer + " (use --solver cpu)";
    return nullptr;
  }
  return GpuSolver::create(error);
}

}  // namespace csm
