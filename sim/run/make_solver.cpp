#include "sim/run/make_solver.h"

#include "gl/caps.h"
#include "gl/draw.h"
#include "sim/solver/cpu_solver.h"
#include "sim/gpu/gpu_solver.h"

namespace csm {

std::unique_ptr<Solver> makeSolver(const std::string& name, std::string* error) {
  if (name == "cpu") return std::make_unique<CpuSolver>();
  if (name == "gpu") return makeGpuSolver(error);
  if (error) *error = "unknown solver \"" + name + "\" (solvers: cpu, gpu)";
  return nullptr;
}

std::unique_ptr<Solver> makeGpuSolver(std::string* error) {
  // Without a current context GL calls go to the dispatcher's no-op stubs: GL_VERSION is null.
  if (gl::versionString() == nullptr) {
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
