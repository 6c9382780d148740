// Compares two PNGs for install_test.sh (the host example against `antumbra render`, and
// with its overlay against without), in the render tests' golden tolerance: at least 99.5%
// of pixels within 3/255 in every channel, and a mean difference below 0.5/255.
//   antumbra_png_compare A.png B.png             the golden tolerance over the whole image
//   antumbra_png_compare A.png B.png --rows Y0 Y1
//       the golden tolerance outside rows Y0..Y1 (inclusive), and some pixel of those rows
//       differing by more than it (what an overlay drawn there changed)
// Exit 0 when the images compare as asked, 1 when not, 2 on a usage or read error.
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <stb_image.h>

namespace {

struct Png {
  int width = 0;
  int height = 0;
  std::vector<unsigned char> rgba;
};

bool load(const char* path, Png& png) {
  int channels = 0;
  unsigned char* data = stbi_load(path, &png.width, &png.height, &channels, 4);
  if (data == nullptr) {
    std::fprintf(stderr, "png_compare: cannot read %s: %s\n", path, stbi_failure_reason());
    return false;
  }
  png.rgba.assign(data, data + static_cast<std::size_t>(png.width) * png.height * 4);
  stbi_image_free(data);
  return true;
}

struct Tally {
  long pixels = 0;
  long over = 0;  // pixels with a channel more than 3/255 off
  double sum = 0.0;
  int max = 0;
  [[nodiscard]] bool golden() const {
    return pixels == 0 || (static_cast<double>(over) <= 0.005 * static_cast<double>(pixels) &&
                           sum / (4.0 * static_cast<double>(pixels)) < 0.5);
  }
  void print(const char* what) const {
    std::printf("%s: %ld of %ld pixels over 3/255, max %d/255, mean %.4f/255\n", what, over, pixels,
                max, pixels == 0 ? 0.0 : sum / (4.0 * static_cast<double>(pixels)));
  }
};

}  // namespace

int main(int argc, char** argv) {
  const bool rows = argc == 6 && std::string(argv[3]) == "--rows";
  if (argc != 3 && !rows) {
    std::fprintf(stderr, "usage: antumbra_png_compare A.png B.png [--rows Y0 Y1]\n");
    return 2;
  }
  Png a;
  Png b;
  if (!load(argv[1], a) || !load(argv[2], b)) return 2;
  if (a.width != b.width || a.height != b.height) {
    std::printf("FAIL: %dx%d against %dx%d\n", a.width, a.height, b.width, b.height);
    return 1;
  }
  const int first = rows ? std::atoi(argv[4]) : a.height;
  const int last = rows ? std::atoi(argv[5]) : -1;
  Tally outside;
  Tally inside;
  for (int y = 0; y < a.height; ++y) {
    Tally& tally = y >= first && y <= last ? inside : outside;
    for (int x = 0; x < a.width; ++x) {
      int pixel_max = 0;
      for (int c = 0; c < 4; ++c) {
        const std::size_t i = (static_cast<std::size_t>(y) * a.width + x) * 4 + c;
        const int d = std::abs(a.rgba[i] - b.rgba[i]);
        pixel_max = d > pixel_max ? d : pixel_max;
        tally.sum += d;
      }
      tally.max = pixel_max > tally.max ? pixel_max : tally.max;
      tally.over += pixel_max > 3 ? 1 : 0;
      ++tally.pixels;
    }
  }
  outside.print(rows ? "outside the rows" : "image");
  if (rows) inside.print("within the rows");
  const bool ok = outside.golden() && (!rows || inside.over > 0);
  std::printf("%s\n", ok ? "PASS" : "FAIL");
  return ok ? 0 : 1;
}
