#pragma once
// A small PNG chart (no plotting library in Debian's C++ set), text drawn with
// stb_easy_font: one horizontal bar per row, stacked from segments (a scenario's
// per-pass medians) with a whisker for the spread (the frame's p10..p90) and an optional
// marker (a baseline's median), over a labelled value axis and under a legend of the
// segment series.

#include <string>
#include <vector>

namespace antumbra::app {

struct StackedRow {
  std::string label;
  std::vector<double> segments;  // by series index; shorter than the series is fine
  double low = 0.0;              // whisker; drawn when high > low
  double high = 0.0;
  std::string annotation;  // printed after the bar, e.g. "12.3 ms"
  double marker = 0.0;     // a thin vertical line across the bar (a baseline); drawn when > 0
};

struct StackedChart {
  std::string title;
  std::string axis_label;           // under the value axis, e.g. "GPU ms per frame"
  std::vector<std::string> series;  // legend, one colour each
  std::vector<StackedRow> rows;
};

// Axis ticks: a 1, 2 or 5 times a power of ten step giving at most `max_ticks` steps
// to reach `max_value` (> 0).
double nice_tick_step(double max_value, int max_ticks);

// Writes atomically (a temporary renamed over `path`); throws std::runtime_error when the
// file cannot be written.
void write_stacked_chart(const std::string& path, const StackedChart& chart);

}  // namespace antumbra::app
