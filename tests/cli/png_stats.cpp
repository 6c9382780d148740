// Prints "WxH colours=N" for a PNG: the editor window test's check that a screenshot
// is the expected size and not blank (a blank image has one colour).
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <unordered_set>

#include <stb_image.h>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: png_stats FILE.png\n");
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
