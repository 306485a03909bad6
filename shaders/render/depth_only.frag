// Depth-only passes (nearest hair from the light, head from the light): no colour output.
void main() {}
