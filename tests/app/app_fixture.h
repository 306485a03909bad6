// The viewer's logic as tests/app drive it: a session on the CPU solver, as fast as it goes, with
// no window and no GL.
#pragma once

#include <memory>
#include <string>

#include <catch2/catch.hpp>

#include "app/preset.h"
#include "app/viewer_session.h"

namespace csm::test {

// A session on the CPU solver (or `make`'s), stopping at `frameLimit` (-1: never).
inline std::unique_ptr<ViewerSession> makeSession(long frameLimit = -1, SolverByName make = {}) {
  SessionOptions o;
  o.solver = "cpu";
  o.makeSolver = std::move(make);
  o.paced = false;
  o.frameLimit = frameLimit;
  o.quiet = true;
  std::string error;
  std::unique_ptr<ViewerSession> s = ViewerSession::create(std::move(o), &error);
  INFO(error);
  REQUIRE(s);
  return s;
}

// The default preset with `strands` strands and no children.
inline Preset smallPreset(int strands) {
  Preset p = defaultPreset();
  p.scene.hairstyle.strands = strands;
  p.view.render.children = 0;
  return p;
}

}  // namespace csm::test
