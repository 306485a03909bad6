// Included by test/double.comp; FACTOR can be overridden by a define.
#ifndef FACTOR
#define FACTOR 2.0
#endif

float scale(float x) { return FACTOR * x; }
