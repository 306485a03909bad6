// The included file has an error on its line 4.
#include "test/broken.glsl"

layout(local_size_x = 1) in;

void main() {}
