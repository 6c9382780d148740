// The console printer of long scene loads: silent for short loads, throttled, and a
// closing line only after it said something.
#include "antumbra/runtime/load_progress.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

namespace antumbra::runtime {
namespace {

std::string read_all(std::FILE* file) {
  std::rewind(file);
  std::string out;
  for (int c = std::fgetc(file); c != EOF; c = std::fgetc(file))
    out.push_back(static_cast<char>(c));
  return out;
}

TEST(LoadProgress, ShortLoadsStaySilentLongOnesAreThrottled) {
  double now = 0.0;
  std::FILE* out = std::tmpfile();
  ASSERT_NE(out, nullptr);
  {
    LoadProgressPrinter quick(out, 500.0, 500.0, [&] { return now; });
    const auto sink = quick.sink();
    now = 100.0;
    sink("reading a.glb", 0, 0);
    quick.finish();
    EXPECT_EQ(quick.lines(), 0);
  }
  EXPECT_EQ(read_all(out), "");

  now = 0.0;
  LoadProgressPrinter slow(out, 500.0, 500.0, [&] { return now; });
  const auto sink = slow.sink();
  for (int i = 1; i <= 100; ++i) {  // 100 images, 20 ms each
    now = 20.0 * i;
    sink("decoding the images of big.glb", static_cast<std::size_t>(i), 100);
  }
  slow.finish();
  // First line at 500 ms, then every 500 ms: 500, 1000, 1500, 2000.
  EXPECT_EQ(slow.lines(), 4);
  const std::string text = read_all(out);
  EXPECT_NE(text.find("loading: decoding the images of big.glb 25/100 (0.5 s)\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("loading: done in 2.0 s\n"), std::string::npos) << text;
  std::fclose(out);
}

}  // namespace
}  // namespace antumbra::runtime
