// A line of the viewer's Messages panel.
#pragma once

#include <chrono>
#include <string>

namespace csm {

enum class MessageLevel { Info, Warning, Error };
struct ViewerMessage {
  MessageLevel level;
  std::string text;
  std::chrono::steady_clock::time_point when;
};

}  // namespace csm
