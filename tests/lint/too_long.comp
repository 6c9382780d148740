#version 460
// A fixture of tests/lint (scripts/lint.py --glsl): formatted, but `eighty_one` spans 81
// lines, one more than lint allows. `eighty` is at the limit, and the functions whose
// head sits in a preprocessor arm or inside a macro must not be taken for long ones.
layout(local_size_x = 1) in;

layout(set = 0, binding = 0) buffer Values {
  float values[];
};

#define ADD_TWICE(x) \
  {                  \
    values[0] += x;  \
    values[0] += x;  \
  }

#ifdef WIDE
vec4 pick(vec4 a, vec4 b) {
#else
vec4 pick(vec4 a) {
  vec4 b = a;
#endif
  return a + b;
}

void eighty() {
  values[1] = 1.0;
  values[2] = 2.0;
  values[3] = 3.0;
  values[4] = 4.0;
  values[5] = 5.0;
  values[6] = 6.0;
  values[7] = 7.0;
  values[8] = 8.0;
  values[9] = 9.0;
  values[10] = 10.0;
  values[11] = 11.0;
  values[12] = 12.0;
  values[13] = 13.0;
  values[14] = 14.0;
  values[15] = 15.0;
  values[16] = 16.0;
  values[17] = 17.0;
  values[18] = 18.0;
  values[19] = 19.0;
  values[20] = 20.0;
  values[21] = 21.0;
  values[22] = 22.0;
  values[23] = 23.0;
  values[24] = 24.0;
  values[25] = 25.0;
  values[26] = 26.0;
  values[27] = 27.0;
  values[28] = 28.0;
  values[29] = 29.0;
  values[30] = 30.0;
  values[31] = 31.0;
  values[32] = 32.0;
  values[33] = 33.0;
  values[34] = 34.0;
  values[35] = 35.0;
  values[36] = 36.0;
  values[37] = 37.0;
  values[38] = 38.0;
  values[39] = 39.0;
  values[40] = 40.0;
  values[41] = 41.0;
  values[42] = 42.0;
  values[43] = 43.0;
  values[44] = 44.0;
  values[45] = 45.0;
  values[46] = 46.0;
  values[47] = 47.0;
  values[48] = 48.0;
  values[49] = 49.0;
  values[50] = 50.0;
  values[51] = 51.0;
  values[52] = 52.0;
  values[53] = 53.0;
  values[54] = 54.0;
  values[55] = 55.0;
  values[56] = 56.0;
  values[57] = 57.0;
  values[58] = 58.0;
  values[59] = 59.0;
  values[60] = 60.0;
  values[61] = 61.0;
  values[62] = 62.0;
  values[63] = 63.0;
  values[64] = 64.0;
  values[65] = 65.0;
  values[66] = 66.0;
  values[67] = 67.0;
  values[68] = 68.0;
  values[69] = 69.0;
  values[70] = 70.0;
  values[71] = 71.0;
  values[72] = 72.0;
  values[73] = 73.0;
  values[74] = 74.0;
  values[75] = 75.0;
  values[76] = 76.0;
  values[77] = 77.0;
  values[78] = 78.0;
  values[79] = 79.0;
}

void eighty_one() {
  values[1] = 1.0;
  values[2] = 2.0;
  values[3] = 3.0;
  values[4] = 4.0;
  values[5] = 5.0;
  values[6] = 6.0;
  values[7] = 7.0;
  values[8] = 8.0;
  values[9] = 9.0;
  values[10] = 10.0;
  values[11] = 11.0;
  values[12] = 12.0;
  values[13] = 13.0;
  values[14] = 14.0;
  values[15] = 15.0;
  values[16] = 16.0;
  values[17] = 17.0;
  values[18] = 18.0;
  values[19] = 19.0;
  values[20] = 20.0;
  values[21] = 21.0;
  values[22] = 22.0;
  values[23] = 23.0;
  values[24] = 24.0;
  values[25] = 25.0;
  values[26] = 26.0;
  values[27] = 27.0;
  values[28] = 28.0;
  values[29] = 29.0;
  values[30] = 30.0;
  values[31] = 31.0;
  values[32] = 32.0;
  values[33] = 33.0;
  values[34] = 34.0;
  values[35] = 35.0;
  values[36] = 36.0;
  values[37] = 37.0;
  values[38] = 38.0;
  values[39] = 39.0;
  values[40] = 40.0;
  values[41] = 41.0;
  values[42] = 42.0;
  values[43] = 43.0;
  values[44] = 44.0;
  values[45] = 45.0;
  values[46] = 46.0;
  values[47] = 47.0;
  values[48] = 48.0;
  values[49] = 49.0;
  values[50] = 50.0;
  values[51] = 51.0;
  values[52] = 52.0;
  values[53] = 53.0;
  values[54] = 54.0;
  values[55] = 55.0;
  values[56] = 56.0;
  values[57] = 57.0;
  values[58] = 58.0;
  values[59] = 59.0;
  values[60] = 60.0;
  values[61] = 61.0;
  values[62] = 62.0;
  values[63] = 63.0;
  values[64] = 64.0;
  values[65] = 65.0;
  values[66] = 66.0;
  values[67] = 67.0;
  values[68] = 68.0;
  values[69] = 69.0;
  values[70] = 70.0;
  values[71] = 71.0;
  values[72] = 72.0;
  values[73] = 73.0;
  values[74] = 74.0;
  values[75] = 75.0;
  values[76] = 76.0;
  values[77] = 77.0;
  values[78] = 78.0;
  values[79] = 79.0;
  values[80] = 80.0;
}

void main() {
  eighty();
  eighty_one();
  ADD_TWICE(1.0)
}
