// A fixture of tests/lint (scripts/lint.py --glsl): short functions, one line that
// clang-format would break (the block on one line).
layout(set = 0, binding = 0) buffer Values { float values[]; };

float first_value() {
  return values[0];
}
