#pragma once
// Chrome / Perfetto trace events ("X" complete events), written as JSON.

#include <cstdint>
#include <string>
#include <vector>

namespace antumbra::runtime {

struct TraceEvent {
  std::string name;
  std::string category;  // "cpu" or "gpu"
  double start_us = 0.0;
  double duration_us = 0.0;
  int thread = 0;  // 1 CPU stages, 2 GPU passes
};

class TraceWriter {
 public:
  void add(TraceEvent event) { events_.push_back(std::move(event)); }
  [[nodiscard]] const std::vector<TraceEvent>& events() const { return events_; }
  // Throws std::runtime_error when the file cannot be written.
  void write(const std::string& path) const;

 private:
  std::vector<TraceEvent> events_;
};

}  // namespace antumbra::runtime
