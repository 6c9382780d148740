#include "plot.hpp"

#include <algorithm>
#include <cstdint>
#include <stdexcept>

#include <stb_easy_font.h>
#include <stb_image_write.h>

namespace antumbra::app {
namespace {

struct Canvas {
  int width;
  int height;
  std::vector<std::uint8_t> rgb;

  Canvas(int w, int h) : width(w), height(h), rgb(static_cast<std::size_t>(w * h * 3), 255) {}

  void fill(int x0, int y0, int x1, int y1, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    x0 = std::clamp(x0, 0, width);
    x1 = std::clamp(x1, 0, width);
    y0 = std::clamp(y0, 0, height);
    y1 = std::clamp(y1, 0, height);
    for (int y = y0; y < y1; ++y) {
      for (int x = x0; x < x1; ++x) {
        auto* p = &rgb[static_cast<std::size_t>((y * width + x) * 3)];
        p[0] = r;
        p[1] = g;
        p[2] = b;
      }
    }
  }

  // stb_easy_font emits axis-aligned quads (4 vertices of x, y, z, rgba).
  void text(int x, int y, const std::string& s) {
    static thread_local std::vector<char> buffer(1 << 16);
    std::string copy = s;
    const int quads = stb_easy_font_print(static_cast<float>(x), static_cast<float>(y), copy.data(),
                                          nullptr, buffer.data(), static_cast<int>(buffer.size()));
    const auto* v = reinterpret_cast<const float*>(buffer.data());
    for (int q = 0; q < quads; ++q) {
      const float* quad = v + q * 16;  // 4 vertices x 4 floats
      fill(static_cast<int>(quad[0]), static_cast<int>(quad[1]), static_cast<int>(quad[8]),
           static_cast<int>(quad[9]), 20, 20, 20);
    }
  }
};

}  // namespace

void write_bar_chart(const std::string& path, const std::string& title,
                     const std::vector<BarRow>& rows) {
  constexpr int kRow = 14;
  constexpr int kLabel = 280;
  constexpr int kBar = 640;
  const int width = kLabel + kBar + 120;
  const int height = 40 + kRow * static_cast<int>(rows.size()) + 10;
  Canvas canvas(width, height);
  canvas.text(10, 10, title);
  double max_value = 0.0;
  for (const auto& r : rows) max_value = std::max(max_value, r.value);
  if (max_value <= 0.0) max_value = 1.0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const int y = 36 + static_cast<int>(i) * kRow;
    if (i % 2 == 0) canvas.fill(0, y - 2, width, y + kRow - 2, 244, 244, 248);
    canvas.text(10, y, rows[i].label);
    const int bar = static_cast<int>(rows[i].value / max_value * kBar);
    canvas.fill(kLabel, y, kLabel + std::max(bar, 1), y + kRow - 4, 70, 110, 190);
    canvas.text(kLabel + bar + 6, y, rows[i].annotation);
  }
  if (stbi_write_png(path.c_str(), width, height, 3, canvas.rgb.data(), width * 3) == 0) {
    throw std::runtime_error("cannot write " + path);
  }
}

}  // namespace antumbra::app
