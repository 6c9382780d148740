#include "antumbra/runtime/load_progress.hpp"

#include <utility>

namespace antumbra::runtime {

LoadProgressPrinter::LoadProgressPrinter(std::FILE* out, double quiet_ms, double interval_ms,
                                         Clock clock)
    : out_(out),
      quiet_ms_(quiet_ms),
      interval_ms_(interval_ms),
      clock_(std::move(clock)),
      start_ms_(clock_()) {
}

double LoadProgressPrinter::steady_ms() {
  return std::chrono::duration<double, std::milli>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

scene::LoadProgress LoadProgressPrinter::sink() {
  return [this](std::string_view stage, std::size_t done, std::size_t total) {
    report(stage, done, total);
  };
}

void LoadProgressPrinter::report(std::string_view stage, std::size_t done, std::size_t total) {
  const double now = clock_();
  if (now - start_ms_ < quiet_ms_ || now - last_ms_ < interval_ms_) return;
  last_ms_ = now;
  ++lines_;
  if (total > 0) {
    std::fprintf(out_, "loading: %.*s %zu/%zu (%.1f s)\n", static_cast<int>(stage.size()),
                 stage.data(), done, total, (now - start_ms_) / 1000.0);
  } else {
    std::fprintf(out_, "loading: %.*s (%.1f s)\n", static_cast<int>(stage.size()), stage.data(),
                 (now - start_ms_) / 1000.0);
  }
  std::fflush(out_);
}

void LoadProgressPrinter::finish() {
  if (lines_ == 0) return;
  std::fprintf(out_, "loading: done in %.1f s\n", (clock_() - start_ms_) / 1000.0);
  std::fflush(out_);
}

}  // namespace antumbra::runtime
