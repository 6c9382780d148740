// Prints "WxH colours=N" for a PNG: the editor window test's check that a screenshot
// is the expected size and not blank (a blank image has one colour).
//   png_stats FILE X Y W H   the mean of each channel over that rectangle: "mean=R G B"
//   png_stats FILE X Y       that pixel: "pixel=R G B"
// (the node view test: a frame brighter after an exposure edit, a wire drawn).
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <unordered_set>

#include <stb_image.h>

int main(int argc, char** argv) {
  if (argc != 2 && argc != 4 && argc != 6) {
    std::fprintf(stderr, "usage: png_stats FILE.png [X Y [W H]]\n");
    return 2;
  }
  int width = 0;
  int height = 0;
  int channels = 0;
  unsigned char* pixels = stbi_load(argv[1], &width, &height, &channels, 4);
  if (pixels == nullptr) {
    std::fprintf(stderr, "png_stats: cannot read %s: %s\n", argv[1], stbi_failure_reason());
    return 1;
  }
  if (argc > 2) {
    const int x0 = std::atoi(argv[2]);
    const int y0 = std::atoi(argv[3]);
    const int w = argc == 6 ? std::atoi(argv[4]) : 1;
    const int h = argc == 6 ? std::atoi(argv[5]) : 1;
    if (x0 < 0 || y0 < 0 || w < 1 || h < 1 || x0 + w > width || y0 + h > height) {
      std::fprintf(stderr, "png_stats: the rectangle is outside the %dx%d image\n", width, height);
      stbi_image_free(pixels);
      return 1;
    }
    double sum[3] = {0.0, 0.0, 0.0};
    for (int y = y0; y < y0 + h; ++y) {
      for (int x = x0; x < x0 + w; ++x) {
        for (int c = 0; c < 3; ++c)
          sum[c] += pixels[(static_cast<std::size_t>(y) * width + x) * 4 + c];
      }
    }
    const double n = static_cast<double>(w) * h;
    std::printf(argc == 6 ? "mean=%.1f %.1f %.1f\n" : "pixel=%.0f %.0f %.0f\n", sum[0] / n,
                sum[1] / n, sum[2] / n);
    stbi_image_free(pixels);
    return 0;
  }
  std::unordered_set<std::uint32_t> colours;
  for (int i = 0; i < width * height; ++i) {
    std::uint32_t rgba = 0;
    std::memcpy(&rgba, pixels + static_cast<std::size_t>(i) * 4, 4);
    colours.insert(rgba);
  }
  stbi_image_free(pixels);
  std::printf("%dx%d colours=%zu\n", width, height, colours.size());
  return 0;
}
