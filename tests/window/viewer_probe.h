// What the window tests read of the viewer beyond its interface (app/viewer.h): the picture's
// state, the last screenshot's pixels, a screenshot still to take, the shaders reloaded as F5 does.
#pragma once

#include "app/scene_view.h"
#include "app/viewer.h"
#include "app/viewer_image.h"

namespace csm {

class ViewerProbe {
 public:
  explicit ViewerProbe(Viewer& viewer) : viewer_(viewer) {}

  const SceneView& sceneView() const { return *viewer_.view_; }
  bool reloadShaders() { return viewer_.reloadShaders(); }
  bool screenshotPending() const { return viewer_.screenshotPending(); }
  const Image& lastScreenshot() const { return viewer_.lastScreenshot_; }

 private:
  Viewer& viewer_;
};

}  // namespace csm
