#include "plot.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numeric>
#include <stdexcept>
#include <string>

#include <stb_easy_font.h>
#include <stb_image_write.h>

#include "antumbra/editor/atomic_file.hpp"

namespace antumbra::app {
namespace {

using Rgb = std::array<std::uint8_t, 3>;

constexpr Rgb kInk{20, 20, 20};
constexpr Rgb kGrid{220, 220, 226};
constexpr Rgb kStripe{244, 244, 248};
// Not in the series palette, so a marker reads apart from every segment.
constexpr Rgb kMarker{200, 0, 140};

struct Canvas {
  int width;
  int height;
  std::vector<std::uint8_t> rgb;

  Canvas(int w, int h) : width(w), height(h), rgb(static_cast<std::size_t>(w * h * 3), 255) {}

  void fill(int x0, int y0, int x1, int y1, Rgb c) {
    x0 = std::clamp(x0, 0, width);
    x1 = std::clamp(x1, 0, width);
    y0 = std::clamp(y0, 0, height);
    y1 = std::clamp(y1, 0, height);
    for (int y = y0; y < y1; ++y) {
      for (int x = x0; x < x1; ++x) {
        std::copy(c.begin(), c.end(), &rgb[(static_cast<std::size_t>(y) * width + x) * 3]);
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
      const float* quad = v + static_cast<std::ptrdiff_t>(q) * 16;  // 4 vertices x 4 floats
      fill(static_cast<int>(quad[0]), static_cast<int>(quad[1]), static_cast<int>(quad[8]),
           static_cast<int>(quad[9]), kInk);
    }
  }
};

int text_width(const std::string& s) {
  std::string copy = s;
  return stb_easy_font_width(copy.data());
}

// Tableau 10 (distinct for most readers, colour-blind included), then golden-ratio hues.
Rgb series_colour(std::size_t index) {
  static constexpr std::array<Rgb, 10> kPalette{{{78, 121, 167},
                                                 {242, 142, 43},
                                                 {225, 87, 89},
                                                 {118, 183, 178},
                                                 {89, 161, 79},
                                                 {237, 201, 72},
                                                 {176, 122, 161},
                                                 {255, 157, 167},
                                                 {156, 117, 95},
                                                 {186, 176, 172}}};
  if (index < kPalette.size()) return kPalette[index];
  const double h = std::fmod(0.618034 * static_cast<double>(index), 1.0) * 6.0;
  const double f = h - std::floor(h);
  const double v = 0.8;
  const double p = v * 0.4;
  const double q = v * (1 - 0.6 * f);
  const double t = v * (1 - 0.6 * (1 - f));
  const std::array<std::array<double, 3>, 6> sectors{
      {{v, t, p}, {q, v, p}, {p, v, t}, {p, q, v}, {t, p, v}, {v, p, q}}};
  const auto& c = sectors[static_cast<std::size_t>(h) % 6];
  return {static_cast<std::uint8_t>(c[0] * 255), static_cast<std::uint8_t>(c[1] * 255),
          static_cast<std::uint8_t>(c[2] * 255)};
}

std::string tick_label(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

constexpr int kRow = 14;
constexpr int kLabel = 250;
constexpr int kBar = 640;
constexpr int kWidth = kLabel + kBar + 360;  // room for an annotation with a baseline's ratio

// Wraps the legend over as many lines as it needs; returns the y below it.
int draw_legend(Canvas* canvas, const std::vector<std::string>& series, int y) {
  int x = 10;
  for (std::size_t i = 0; i < series.size(); ++i) {
    const int item = 14 + text_width(series[i]) + 14;
    if (x + item > kWidth - 10) {
      x = 10;
      y += kRow;
    }
    if (canvas != nullptr) {
      canvas->fill(x, y, x + 10, y + 8, series_colour(i));
      canvas->text(x + 14, y, series[i]);
    }
    x += item;
  }
  return y + kRow + 6;
}

void draw_row(Canvas& canvas, const StackedRow& row, int y, double px_per_unit) {
  canvas.text(10, y, row.label);
  double start = 0.0;
  for (std::size_t s = 0; s < row.segments.size(); ++s) {
    const double end = start + std::max(row.segments[s], 0.0);
    const int x0 = kLabel + static_cast<int>(std::lround(start * px_per_unit));
    const int x1 = kLabel + static_cast<int>(std::lround(end * px_per_unit));
    if (x1 > x0) canvas.fill(x0, y, x1, y + kRow - 4, series_colour(s));
    start = end;
  }
  int right = kLabel + static_cast<int>(std::lround(start * px_per_unit));
  if (row.high > row.low) {
    const int lo = kLabel + static_cast<int>(std::lround(row.low * px_per_unit));
    const int hi = kLabel + static_cast<int>(std::lround(row.high * px_per_unit));
    const int mid = y + (kRow - 4) / 2;
    canvas.fill(lo, mid - 1, std::max(hi, lo + 1), mid + 1, kInk);
    canvas.fill(lo, y - 1, lo + 1, y + kRow - 3, kInk);
    canvas.fill(hi - 1, y - 1, hi, y + kRow - 3, kInk);
    right = std::max(right, hi);
  }
  if (row.marker > 0.0) {
    const int x = kLabel + static_cast<int>(std::lround(row.marker * px_per_unit));
    canvas.fill(x - 1, y - 2, x + 1, y + kRow - 2, kMarker);
    right = std::max(right, x + 1);
  }
  canvas.text(right + 6, y, row.annotation);
}

void draw_axis(Canvas& canvas, const StackedChart& chart, int bottom, double step, int ticks,
               double px_per_unit) {
  canvas.fill(kLabel, bottom, kLabel + kBar + 1, bottom + 1, kInk);
  for (int t = 0; t <= ticks; ++t) {
    const double value = step * t;
    const int x = kLabel + static_cast<int>(std::lround(value * px_per_unit));
    canvas.fill(x, bottom, x + 1, bottom + 4, kInk);
    const std::string label = tick_label(value);
    canvas.text(x - text_width(label) / 2, bottom + 6, label);
  }
  canvas.text(kLabel + (kBar - text_width(chart.axis_label)) / 2, bottom + 20, chart.axis_label);
}

void draw_grid(Canvas& canvas, int top, int bottom, double step, int ticks, double px_per_unit) {
  for (int t = 0; t <= ticks; ++t) {
    const int x = kLabel + static_cast<int>(std::lround(step * t * px_per_unit));
    canvas.fill(x, top, x + 1, bottom, kGrid);
  }
}

}  // namespace

double nice_tick_step(double max_value, int max_ticks) {
  const double raw = max_value / std::max(max_ticks, 1);
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  for (const double m : {1.0, 2.0, 5.0}) {
    if (m * power >= raw * (1 - 1e-6)) return m * power;  // float inputs: 0.1f is 0.1
  }
  return 10.0 * power;
}

void write_stacked_chart(const std::string& path, const StackedChart& chart) {
  double max_value = 0.0;
  for (const auto& r : chart.rows) {
    max_value = std::max(
        {max_value, std::accumulate(r.segments.begin(), r.segments.end(), 0.0), r.high, r.marker});
  }
  if (!(max_value > 0.0)) max_value = 1.0;
  const double step = nice_tick_step(max_value, 8);
  const int ticks = static_cast<int>(std::ceil(max_value / step - 1e-9));
  const double px_per_unit = kBar / (step * ticks);

  const int legend_bottom = draw_legend(nullptr, chart.series, 28);
  const int rows_top = legend_bottom + 4;
  const int rows_bottom = rows_top + kRow * static_cast<int>(chart.rows.size());
  Canvas canvas(kWidth, rows_bottom + 40);
  canvas.text(10, 10, chart.title);
  draw_legend(&canvas, chart.series, 28);
  for (std::size_t i = 0; i < chart.rows.size(); i += 2) {
    const int y = rows_top + static_cast<int>(i) * kRow;
    canvas.fill(0, y - 2, kWidth, y + kRow - 2, kStripe);
  }
  draw_grid(canvas, rows_top - 2, rows_bottom, step, ticks, px_per_unit);
  for (std::size_t i = 0; i < chart.rows.size(); ++i) {
    draw_row(canvas, chart.rows[i], rows_top + static_cast<int>(i) * kRow, px_per_unit);
  }
  draw_axis(canvas, chart, rows_bottom, step, ticks, px_per_unit);
  // Encoded in memory and renamed into place: `bench` rewrites its chart after every
  // scenario, and a run killed meanwhile must not leave half a PNG.
  std::string png;
  const auto append = [](void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                               static_cast<std::size_t>(size));
  };
  if (stbi_write_png_to_func(append, &png, canvas.width, canvas.height, 3, canvas.rgb.data(),
                             canvas.width * 3) == 0) {
    throw std::runtime_error("cannot encode " + path);
  }
  editor::write_file_atomically(path, png);
}

}  // namespace antumbra::app
