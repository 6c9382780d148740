#pragma once
// The console side of scene::LoadProgress: a long load (a large glTF, many images) says
// what it is doing, a short one stays silent. Lines go to stderr so that --json output
// on stdout stays clean.

#include <chrono>
#include <cstdio>
#include <functional>
#include <string>

#include "antumbra/scene/image_cache.hpp"

namespace antumbra::runtime {

class LoadProgressPrinter {
 public:
  using Clock = std::function<double()>;  // milliseconds since any fixed point

  // Nothing is printed before `quiet_ms` have passed, then one line at most every
  // `interval_ms` and a last one when finish() is called after a printed line.
  explicit LoadProgressPrinter(std::FILE* out = stderr, double quiet_ms = 500.0,
                               double interval_ms = 500.0, Clock clock = steady_ms);

  [[nodiscard]] scene::LoadProgress sink();
  void finish();
  [[nodiscard]] int lines() const { return lines_; }

  static double steady_ms();

 private:
  void report(std::string_view stage, std::size_t done, std::size_t total);

  std::FILE* out_;
  double quiet_ms_;
  double interval_ms_;
  Clock clock_;
  double start_ms_;
  double last_ms_ = -1.0e300;
  int lines_ = 0;
};

}  // namespace antumbra::runtime
