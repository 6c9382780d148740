#pragma once
// A small PNG bar chart (no plotting library in Debian's C++ set): one labelled bar
// per row, text drawn with stb_easy_font.

#include <string>
#include <vector>

namespace antumbra::app {

struct BarRow {
  std::string label;
  double value = 0.0;
  std::string annotation;  // printed after the bar, e.g. "12.3 ms"
};

// Throws std::runtime_error when the file cannot be written.
void write_bar_chart(const std::string& path, const std::string& title,
                     const std::vector<BarRow>& rows);

}  // namespace antumbra::app
