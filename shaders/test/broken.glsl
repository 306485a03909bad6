// Included by test/include_error.comp; the error is on line 4.
float helper(float x) {
  float y = x * 2.0;
  return y + undefined_variable;
}
