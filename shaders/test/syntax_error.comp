// A deliberate syntax error on line 5, for the compile-failure test.
layout(local_size_x = 1) in;

void main() {
  float x = 1.0 +;
}
