#include "antumbra/runtime/trace_writer.hpp"

#include <fstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

namespace antumbra::runtime {

void TraceWriter::write(const std::string& path) const {
  auto events = nlohmann::json::array();
  events.push_back(
      {{"name", "thread_name"}, {"ph", "M"}, {"pid", 1}, {"tid", 1}, {"args", {{"name", "CPU"}}}});
  events.push_back(
      {{"name", "thread_name"}, {"ph", "M"}, {"pid", 1}, {"tid", 2}, {"args", {{"name", "GPU"}}}});
  for (const auto& e : events_) {
    events.push_back({{"name", e.name},
                      {"cat", e.category},
                      {"ph", "X"},
                      {"ts", e.start_us},
                      {"dur", e.duration_us},
                      {"pid", 1},
                      {"tid", e.thread}});
  }
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write the trace file " + path);
  out << nlohmann::json{{"traceEvents", events}, {"displayTimeUnit", "ms"}}.dump(1) << '\n';
  if (!out) throw std::runtime_error("failed writing the trace file " + path);
}

}  // namespace antumbra::runtime
