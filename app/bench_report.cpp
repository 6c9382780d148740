#include "bench_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace antumbra::app {

double percentile(std::vector<double> values, double p) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const double rank = std::clamp(p, 0.0, 100.0) / 100.0 * static_cast<double>(values.size() - 1);
  const auto below = static_cast<std::size_t>(std::floor(rank));
  const std::size_t above = std::min(below + 1, values.size() - 1);
  const double t = rank - static_cast<double>(below);
  return values[below] + t * (values[above] - values[below]);
}

TimingStats summarize(const std::vector<double>& samples_ms) {
  return {percentile(samples_ms, 50.0), percentile(samples_ms, 10.0), percentile(samples_ms, 90.0),
          samples_ms.size()};
}

std::vector<double> frame_samples(const std::vector<std::vector<double>>& per_pass) {
  if (per_pass.empty()) return {};
  std::size_t frames = per_pass.front().size();
  for (const auto& pass : per_pass) frames = std::min(frames, pass.size());
  std::vector<double> sums(frames, 0.0);
  for (const auto& pass : per_pass) {
    for (std::size_t i = 0; i < frames; ++i) sums[i] += pass[i];
  }
  return sums;
}

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

namespace {

void write_row(std::ostream& out, const BenchResult& r, const std::string& pass,
               const std::string& type, const TimingStats* stats) {
  const auto& s = r.scenario;
  out << csv_field(s.name) << ',' << s.table << ',' << s.technique << ',' << s.kernel << ','
      << s.width << ',' << s.height << ',' << s.face << ',' << s.lights << ',' << s.moving << ','
      << csv_field(s.scene) << ',' << s.rasterizer << ',' << s.light_size << ',' << r.status << ','
      << csv_field(pass) << ',' << csv_field(type) << ',';
  if (stats != nullptr) {
    out << stats->median_ms << ',' << stats->p10_ms << ',' << stats->p90_ms << ',' << stats->frames;
  } else {
    out << ",,,0";
  }
  out << '\n';
}

nlohmann::json stats_json(const TimingStats& s) {
  return {
      {"medianMs", s.median_ms}, {"p10Ms", s.p10_ms}, {"p90Ms", s.p90_ms}, {"frames", s.frames}};
}

}  // namespace

void write_long_csv(std::ostream& out, const std::vector<BenchResult>& results) {
  out << "scenario,table,technique,kernel,width,height,atlas_face,lights,moving_lights,scene,"
         "rasterizer,light_size,status,"
         "pass,pass_type,"
         "median_ms,p10_ms,p90_ms,frames\n";
  for (const auto& r : results) {
    const bool ok = r.status == "ok";
    if (ok) {
      for (const auto& p : r.passes) write_row(out, r, p.name, p.type, &p.gpu);
    }
    write_row(out, r, "frame", "", ok ? &r.frame : nullptr);
    for (const auto& step : r.steps) write_row(out, r, step.name, "step:" + step.type, &step.gpu);
  }
}

nlohmann::json results_json(const std::vector<BenchResult>& results) {
  auto scenarios = nlohmann::json::array();
  for (const auto& r : results) {
    auto passes = nlohmann::json::array();
    for (const auto& p : r.passes) {
      auto pass = stats_json(p.gpu);
      pass["name"] = p.name;
      pass["type"] = p.type;
      pass["cpuMedianMs"] = p.cpu_median_ms;
      passes.push_back(std::move(pass));
    }
    const auto& s = r.scenario;
    scenarios.push_back({{"scenario", s.name},
                         {"table", s.table},
                         {"technique", s.technique},
                         {"kernel", s.kernel},
                         {"width", s.width},
                         {"height", s.height},
                         {"atlasFace", s.face},
                         {"lights", s.lights},
                         {"movingLights", s.moving},
                         {"scene", s.scene},
                         {"rasterizer", s.rasterizer},
                         {"lightSize", s.light_size},
                         {"shadowCache", s.shadow_cache},
                         {"status", r.status},
                         {"detail", r.detail},
                         {"frame", stats_json(r.frame)},
                         {"passes", passes}});
    if (!r.notes.empty()) scenarios.back()["notes"] = r.notes;
    if (!r.steps.empty()) {
      auto& steps = scenarios.back()["steps"];
      steps = nlohmann::json::array();
      for (const auto& step : r.steps) {
        auto entry = stats_json(step.gpu);
        entry["name"] = step.name;
        entry["pass"] = step.type;
        steps.push_back(std::move(entry));
      }
    }
  }
  return scenarios;
}

nlohmann::json compact_details(const nlohmann::json& details) {
  if (!details.is_object()) return details.is_array() ? nlohmann::json::object() : details;
  constexpr std::size_t kSmallObject = 1024;  // bytes of JSON kept whole (faceSizes)
  auto out = nlohmann::json::object();
  for (const auto& [key, value] : details.items()) {
    if (value.is_array()) {
      std::string name = key;  // appended: operator+ makes GCC 12 warn falsely (-Wrestrict)
      name += "Count";
      out[name] = value.size();
    } else if (value.is_object() && value.dump().size() > kSmallObject) {
      out[key] = compact_details(value);
    } else {
      out[key] = value;
    }
  }
  return out;
}

nlohmann::json bench_json(const BenchRun& run, const std::vector<BenchResult>& results) {
  auto json = nlohmann::json{{"commit", run.commit},
                             {"device", run.device},
                             {"driver", run.driver},
                             {"frames", run.frames},
                             {"warmup", run.warmup},
                             {"warmupFrom", run.warmup_from},
                             {"scale", run.scale},
                             {"complete", run.finished == run.planned},
                             {"scenariosPlanned", run.planned},
                             {"scenariosFinished", run.finished}};
  if (!run.preset.empty()) json["preset"] = run.preset;
  json["scenarios"] = results_json(results);
  return json;
}

std::string bench_setup_line(const BenchRun& run) {
  const std::string from = run.warmup_from == "--warmup" ? "" : " (" + run.warmup_from + ")";
  char text[160];
  std::snprintf(text, sizeof text,
                ": %zu scenario(s), %d warm-up%s + %d timed frames each, scale %.2f", run.planned,
                run.warmup, from.c_str(), run.frames, run.scale);
  return "bench on " + run.device + text + (run.preset.empty() ? "" : " (--" + run.preset + ")");
}

}  // namespace antumbra::app
