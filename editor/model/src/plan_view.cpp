#include "antumbra/editor/plan_view.hpp"

#include <algorithm>
#include <array>
#include <cstdio>

namespace antumbra::editor {
namespace {

using base::Json;

std::string text_at(const Json& object, std::string_view key) {
  const auto it = object.find(key);
  return it != object.end() && it->is_string() ? it->get<std::string>() : std::string();
}

template <typename T>
T number_at(const Json& object, std::string_view key, T fallback) {
  const auto it = object.find(key);
  return it != object.end() && it->is_number() ? it->get<T>() : fallback;
}

const Json& array_at(const Json& object, std::string_view key) {
  static const Json kEmpty = Json::array();
  const auto it = object.find(key);
  return it != object.end() && it->is_array() ? *it : kEmpty;
}

std::vector<std::string> names_at(const Json& object, std::string_view key) {
  std::vector<std::string> out;
  for (const Json& v : array_at(object, key))
    if (v.is_string()) out.push_back(v.get<std::string>());
  return out;
}

PlanViewBarrier read_barrier(const Json& b) {
  PlanViewBarrier out;
  out.resource = text_at(b, "resource");
  out.source = text_at(b, "source");
  out.from = text_at(b, "from");
  out.from_stage = text_at(b, "fromStage");
  out.to = text_at(b, "to");
  out.to_stage = text_at(b, "toStage");
  const auto d = b.find("discard");
  out.discard = d != b.end() && d->is_boolean() && d->get<bool>();
  return out;
}

std::vector<PlanViewBarrier> read_barriers(const Json& list) {
  std::vector<PlanViewBarrier> out;
  for (const Json& b : list)
    if (b.is_object()) out.push_back(read_barrier(b));
  return out;
}

std::string resource_detail(const Json& r, const std::string& kind) {
  if (kind == "buffer") return std::to_string(number_at<std::uint64_t>(r, "bytes", 0)) + " bytes";
  std::string size = text_at(r, "size");
  const auto s = r.find("size");
  if (size.empty() && s != r.end() && s->is_array() && s->size() == 2) {
    size = s->at(0).dump() + "x" + s->at(1).dump();
  }
  return text_at(r, "format") + " " + size + " x" + std::to_string(number_at<int>(r, "layers", 1));
}

PlanViewLifetime read_lifetime(const Json& r) {
  PlanViewLifetime out;
  out.resource = text_at(r, "name");
  out.kind = text_at(r, "kind");
  out.detail = resource_detail(r, out.kind);
  out.first = number_at<int>(r, "firstUse", -1);
  out.last = number_at<int>(r, "lastUse", -1);
  const auto flag = [&](std::string_view key) {
    const auto it = r.find(key);
    return it != r.end() && it->is_boolean() && it->get<bool>();
  };
  out.persistent = flag("persistent");
  out.imported = flag("imported");
  out.aliased = flag("aliased");
  out.offset = number_at<std::uint64_t>(r, "heapOffset", 0);
  const auto fp = r.find("footprint");
  if (fp != r.end() && fp->is_object()) out.bytes = number_at<std::uint64_t>(*fp, "size", 0);
  return out;
}

// Two aliased resources share memory where their heap ranges overlap.
void find_shared_memory(std::vector<PlanViewLifetime>& lifetimes) {
  for (std::size_t i = 0; i < lifetimes.size(); ++i) {
    PlanViewLifetime& a = lifetimes[i];
    for (std::size_t j = i + 1; j < lifetimes.size(); ++j) {
      PlanViewLifetime& b = lifetimes[j];
      if (!a.aliased || !b.aliased || a.bytes == 0 || b.bytes == 0) continue;
      if (a.offset < b.offset + b.bytes && b.offset < a.offset + a.bytes) {
        a.shares_with.push_back(b.resource);
        b.shares_with.push_back(a.resource);
      }
    }
  }
}

std::optional<PlanViewSchedule> read_schedule(const Json& plan) {
  const auto it = plan.find("schedule");
  if (it == plan.end() || !it->is_object()) return std::nullopt;
  PlanViewSchedule s;
  s.critical_path = names_at(*it, "criticalPath");
  s.critical_ms = number_at<double>(*it, "criticalMs", 0.0);
  s.serial_ms = number_at<double>(*it, "serialMs", 0.0);
  s.overlap_bound_ms = number_at<double>(*it, "overlapBoundMs", 0.0);
  s.weights = text_at(*it, "weights");
  return s;
}

}  // namespace

std::string PlanViewBarrier::text() const {
  std::string out =
      resource + ": " + from + " (" + from_stage + ") -> " + to + " (" + to_stage + ")";
  if (discard) out += ", contents discarded";
  if (!source.empty()) out += " [" + source + "]";
  return out;
}

PlanView build_plan_view(const Json& plan) {
  PlanView view;
  if (!plan.is_object()) return view;
  view.name = text_at(plan, "name");
  for (const Json& p : array_at(plan, "passes")) {
    if (!p.is_object()) continue;
    view.passes.push_back({text_at(p, "name"), text_at(p, "type"),
                           read_barriers(array_at(p, "barriers")), std::nullopt, false});
  }
  for (const Json& r : array_at(plan, "resources"))
    if (r.is_object()) view.lifetimes.push_back(read_lifetime(r));
  find_shared_memory(view.lifetimes);
  view.final_barriers = read_barriers(array_at(plan, "finalBarriers"));
  view.culled = names_at(plan, "culled");
  view.disabled = names_at(plan, "disabled");
  const auto aliasing = plan.find("aliasing");
  if (aliasing != plan.end() && aliasing->is_object()) {
    view.bytes_without_aliasing = number_at<std::uint64_t>(*aliasing, "bytesWithoutAliasing", 0);
    view.heap_bytes = number_at<std::uint64_t>(*aliasing, "heapBytes", 0);
    view.bytes_saved = number_at<std::uint64_t>(*aliasing, "bytesSaved", 0);
  }
  view.schedule = read_schedule(plan);
  if (view.schedule) {
    for (PlanViewPass& p : view.passes) {
      const auto& path = view.schedule->critical_path;
      p.critical = std::find(path.begin(), path.end(), p.name) != path.end();
    }
  }
  return view;
}

void set_pass_times(PlanView& view, const std::map<std::string, double, std::less<>>& times) {
  for (PlanViewPass& p : view.passes) {
    const auto it = times.find(p.name);
    p.gpu_ms = it != times.end() ? std::optional<double>(it->second) : std::nullopt;
  }
}

std::string byte_text(std::uint64_t bytes) {
  constexpr std::array<const char*, 4> kUnits{"B", "KiB", "MiB", "GiB"};
  double value = static_cast<double>(bytes);
  std::size_t unit = 0;
  while (value >= 1024.0 && unit + 1 < kUnits.size()) {
    value /= 1024.0;
    ++unit;
  }
  std::array<char, 32> text{};
  std::snprintf(text.data(), text.size(), unit == 0 ? "%.0f %s" : "%.1f %s", value, kUnits[unit]);
  return text.data();
}

}  // namespace antumbra::editor
