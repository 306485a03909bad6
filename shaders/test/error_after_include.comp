// An error in this file on line 7, after an include: the line count must resume here.
#include "test/common.glsl"

layout(local_size_x = 1) in;

void main() {
  int x = undefined_after_include;
}
