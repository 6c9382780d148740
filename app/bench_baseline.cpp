// Reading a baseline bench.json and matching it with this run (bench_baseline.hpp); the
// text, CSV, JSON and chart of the comparison are in bench_baseline_report.cpp.
#include "bench_baseline.hpp"

#include <cmath>
#include <cstdio>
#include <map>

namespace antumbra::app {
namespace {

using base::Json;

// What a value is, for "expected X, found Y".
std::string describe(const Json* value) {
  if (value == nullptr) return "nothing (the key is missing)";
  if (value->is_null()) return "null";
  if (value->is_boolean()) return "a boolean";
  if (value->is_number()) return "a number";
  if (value->is_string()) return "a string";
  if (value->is_array()) return "an array";
  return "an object";
}

// Reads a document with typed accessors that fail with the file, line:column and JSON
// Pointer of the value at fault (a missing key: its object's position).
class Reader {
 public:
  explicit Reader(const base::JsonDocument& document) : document_(document) {}

  [[noreturn]] void fail(const std::string& pointer, const std::string& expected,
                         const Json* found) const {
    const auto position = document_.position(pointer);
    std::string where = document_.file();
    if (position.line > 0) {
      where += ':' + std::to_string(position.line) + ':' + std::to_string(position.column);
    }
    throw BaselineError(where + ": expected " + expected + " at " +
                        (pointer.empty() ? std::string("/") : pointer) + ", found " +
                        describe(found) + " (not a bench.json as `antumbra bench` writes it)");
  }

  const Json* member(const Json& object, const std::string& key) const {
    const auto it = object.find(key);
    return it == object.end() ? nullptr : &*it;
  }

  const Json& object(const Json& parent, const std::string& pointer, const std::string& key) const {
    const Json* value = member(parent, key);
    if (value == nullptr || !value->is_object()) fail(at(pointer, key), "an object", value);
    return *value;
  }

  const Json& array(const Json& parent, const std::string& pointer, const std::string& key) const {
    const Json* value = member(parent, key);
    if (value == nullptr || !value->is_array()) fail(at(pointer, key), "an array", value);
    return *value;
  }

  // A string member; empty when absent and not `required`.
  std::string text(const Json& parent, const std::string& pointer, const std::string& key,
                   bool required) const {
    const Json* value = member(parent, key);
    if (value == nullptr && !required) return {};
    if (value == nullptr || !value->is_string()) fail(at(pointer, key), "a string", value);
    return value->get<std::string>();
  }

  double number(const Json& parent, const std::string& pointer, const std::string& key) const {
    const Json* value = member(parent, key);
    if (value == nullptr || !value->is_number() || !std::isfinite(value->get<double>())) {
      fail(at(pointer, key), "a number of milliseconds", value);
    }
    return value->get<double>();
  }

  template <class T>
  std::optional<T> optional_number(const Json& parent, const std::string& pointer,
                                   const std::string& key, bool integer) const {
    const Json* value = member(parent, key);
    if (value == nullptr) return std::nullopt;
    if (integer ? !value->is_number_integer() : !value->is_number()) {
      fail(at(pointer, key), integer ? "an integer" : "a number", value);
    }
    return value->get<T>();
  }

  std::optional<bool> optional_bool(const Json& parent, const std::string& pointer,
                                    const std::string& key) const {
    const Json* value = member(parent, key);
    if (value == nullptr) return std::nullopt;
    if (!value->is_boolean()) fail(at(pointer, key), "a boolean", value);
    return value->get<bool>();
  }

  static std::string at(const std::string& pointer, const std::string& key) {
    return base::pointer_append(pointer, key);
  }
  static std::string at(const std::string& pointer, std::size_t index) {
    return base::pointer_append(pointer, index);
  }

 private:
  const base::JsonDocument& document_;
};

BenchResult parse_scenario(const Reader& reader, const Json& json, const std::string& pointer) {
  if (!json.is_object()) reader.fail(pointer, "a scenario object", &json);
  BenchResult r;
  r.scenario.name = reader.text(json, pointer, "scenario", true);
  r.status = reader.text(json, pointer, "status", true);
  r.detail = reader.text(json, pointer, "detail", false);
  // A failed scenario's numbers are zeros at best: they are never compared.
  if (r.status != "ok") return r;
  const auto frame_pointer = Reader::at(pointer, "frame");
  r.frame.median_ms =
      reader.number(reader.object(json, pointer, "frame"), frame_pointer, "medianMs");
  const auto passes_pointer = Reader::at(pointer, "passes");
  const Json& passes = reader.array(json, pointer, "passes");
  for (std::size_t i = 0; i < passes.size(); ++i) {
    const auto pass_pointer = Reader::at(passes_pointer, i);
    if (!passes[i].is_object()) reader.fail(pass_pointer, "a pass object", &passes[i]);
    PassStats pass;
    pass.name = reader.text(passes[i], pass_pointer, "name", true);
    pass.type = reader.text(passes[i], pass_pointer, "type", false);
    pass.gpu.median_ms = reader.number(passes[i], pass_pointer, "medianMs");
    r.passes.push_back(std::move(pass));
  }
  return r;
}

// For each of `later`, the index of the same-named entry of `earlier` (the n-th of a name
// with the n-th), and the entries of `earlier` that none matched.
struct NameMatch {
  std::vector<std::optional<std::size_t>> of_later;
  std::vector<std::size_t> unmatched_earlier;
};

NameMatch match_names(const std::vector<std::string>& earlier,
                      const std::vector<std::string>& later) {
  std::map<std::string, std::vector<std::size_t>> open;  // name -> indices, reversed
  for (std::size_t i = earlier.size(); i-- > 0;) open[earlier[i]].push_back(i);
  std::vector<bool> used(earlier.size(), false);
  NameMatch match;
  for (const auto& name : later) {
    auto it = open.find(name);
    if (it == open.end() || it->second.empty()) {
      match.of_later.emplace_back();
      continue;
    }
    match.of_later.emplace_back(it->second.back());
    used[it->second.back()] = true;
    it->second.pop_back();
  }
  for (std::size_t i = 0; i < earlier.size(); ++i) {
    if (!used[i]) match.unmatched_earlier.push_back(i);
  }
  return match;
}

std::vector<std::string> scenario_names(const std::vector<BenchResult>& results) {
  std::vector<std::string> names;
  names.reserve(results.size());
  for (const auto& r : results) names.push_back(r.scenario.name);
  return names;
}

std::vector<std::string> pass_names(const std::vector<PassStats>& passes) {
  std::vector<std::string> names;
  names.reserve(passes.size());
  for (const auto& p : passes) names.push_back(p.name);
  return names;
}

std::string number_text(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

std::optional<double> frame_ms(const BenchResult& r) {
  return r.status == "ok" ? std::optional<double>(r.frame.median_ms) : std::nullopt;
}

BaselineRow frame_row(BaselineRow::Kind kind, const BenchResult* baseline, const BenchResult* run) {
  BaselineRow row{kind, (run != nullptr ? run : baseline)->scenario.name, "frame"};
  row.frame = true;
  if (baseline != nullptr) {
    row.baseline_ms = frame_ms(*baseline);
    row.baseline_status = baseline->status;
  }
  if (run != nullptr) {
    row.run_ms = frame_ms(*run);
    row.run_status = run->status;
  }
  return row;
}

void set_ratio(BaselineRow& row, const SlowerRule& rule) {
  if (*row.baseline_ms > 0.0) row.ratio = *row.run_ms / *row.baseline_ms;
  row.slower = rule.slower(*row.baseline_ms, *row.run_ms);
}

// Both sides ok: a row per pass (this run's order, then the baseline's extras), the frame.
void compare_passes(BaselineComparison& out, const BenchResult& baseline, const BenchResult& run,
                    std::size_t run_index) {
  const auto match = match_names(pass_names(baseline.passes), pass_names(run.passes));
  for (std::size_t p = 0; p < run.passes.size(); ++p) {
    BaselineRow row{BaselineRow::Kind::only_in_run, run.scenario.name, run.passes[p].name,
                    run.passes[p].type};
    row.run_ms = run.passes[p].gpu.median_ms;
    row.run_scenario = run_index;
    row.run_pass = p;
    if (const auto b = match.of_later[p]) {
      row.kind = BaselineRow::Kind::compared;
      row.baseline_ms = baseline.passes[*b].gpu.median_ms;
      set_ratio(row, out.rule);
    }
    out.rows.push_back(std::move(row));
  }
  for (const std::size_t b : match.unmatched_earlier) {
    const auto& pass = baseline.passes[b];
    BaselineRow row{BaselineRow::Kind::only_in_baseline, run.scenario.name, pass.name, pass.type};
    row.baseline_ms = pass.gpu.median_ms;
    out.rows.push_back(std::move(row));
  }
  auto frame = frame_row(BaselineRow::Kind::compared, &baseline, &run);
  frame.run_scenario = run_index;
  set_ratio(frame, out.rule);
  out.rows.push_back(std::move(frame));
}

}  // namespace

bool SlowerRule::slower(double baseline_ms, double run_ms) const {
  // Medians read back from decimal text: 5 % written as 1.000 -> 1.050 stays 5 %.
  constexpr double kRoundOff = 1e-9;
  if (run_ms - baseline_ms < min_ms - kRoundOff) return false;
  if (baseline_ms <= 0.0) return true;  // time over nothing: an unbounded ratio
  return run_ms / baseline_ms >= ratio - kRoundOff;
}

bool valid_slower_percent(double percent) {
  return std::isfinite(percent) && percent >= 0.0;
}

BenchFile parse_bench_file(const base::JsonDocument& document) {
  const Reader reader(document);
  const Json& root = document.root();
  if (!root.is_object()) reader.fail("", "a bench.json object", &root);
  BenchFile out;
  out.file = document.file();
  out.commit = reader.text(root, "", "commit", false);
  out.device = reader.text(root, "", "device", false);
  out.driver = reader.text(root, "", "driver", false);
  out.frames = reader.optional_number<int>(root, "", "frames", true);
  out.warmup = reader.optional_number<int>(root, "", "warmup", true);
  out.scale = reader.optional_number<double>(root, "", "scale", false);
  out.complete = reader.optional_bool(root, "", "complete");
  out.planned = reader.optional_number<int>(root, "", "scenariosPlanned", true);
  const Json& scenarios = reader.array(root, "", "scenarios");
  for (std::size_t i = 0; i < scenarios.size(); ++i) {
    out.results.push_back(parse_scenario(reader, scenarios[i], Reader::at("/scenarios", i)));
  }
  return out;
}

BenchFile load_bench_file(const std::string& path) {
  auto document = base::load_json_file(path);
  if (!document.ok()) {
    // "B.json:3:7: error[FG001]: ..." or "B.json: error[FG000]: cannot open the file: ...".
    std::string text = document.diagnostics().to_text();
    text.erase(text.find_last_not_of('\n') + 1);  // one line per diagnostic, the last too
    throw BaselineError(text);
  }
  return parse_bench_file(document.value());
}

std::vector<std::string> setup_mismatches(const BenchFile& baseline, const RunSetup& run) {
  std::vector<std::string> lines;
  const std::string from = "the baseline " + baseline.file;
  if (!baseline.device.empty() && baseline.device != run.device) {
    lines.push_back(from + " was measured on " + baseline.device + ", this run on " + run.device +
                    ": ratios across devices mean little");
  }
  const auto differs = [&](const char* what, const auto& theirs, const auto& ours) {
    if (theirs && *theirs != ours) {
      lines.push_back(from + " has " + what + ' ' + number_text(*theirs) + ", this run " +
                      number_text(ours));
    }
  };
  differs("--frames", baseline.frames, run.frames);
  differs("--warmup", baseline.warmup, run.warmup);
  differs("--scale", baseline.scale, run.scale);
  if (baseline.complete.has_value() && !*baseline.complete) {
    const std::string planned = baseline.planned ? std::to_string(*baseline.planned) : "?";
    lines.push_back(from + " is partial (an interrupted run: " +
                    std::to_string(baseline.results.size()) + " of " + planned +
                    " scenarios finished): compared as far as it goes, the scenarios it lacks "
                    "show as only in this run");
  }
  return lines;
}

std::size_t BaselineComparison::count(BaselineRow::Kind kind) const {
  std::size_t n = 0;
  for (const auto& row : rows) n += row.kind == kind ? 1 : 0;
  return n;
}

std::size_t BaselineComparison::slower_count() const {
  std::size_t n = 0;
  for (const auto& row : rows) n += row.slower ? 1 : 0;
  return n;
}

BaselineComparison compare_with_baseline(const std::vector<BenchResult>& baseline,
                                         const std::vector<BenchResult>& run,
                                         const SlowerRule& rule) {
  BaselineComparison out{{}, rule};
  const auto match = match_names(scenario_names(baseline), scenario_names(run));
  for (std::size_t i = 0; i < run.size(); ++i) {
    const auto b = match.of_later[i];
    if (b && baseline[*b].status == "ok" && run[i].status == "ok") {
      compare_passes(out, baseline[*b], run[i], i);
      continue;
    }
    // One side failed, or the scenario is only in this run: one frame row, never a ratio.
    auto row = b ? frame_row(BaselineRow::Kind::failed, &baseline[*b], &run[i])
                 : frame_row(BaselineRow::Kind::only_in_run, nullptr, &run[i]);
    row.run_scenario = i;
    out.rows.push_back(std::move(row));
  }
  for (const std::size_t b : match.unmatched_earlier) {
    out.rows.push_back(frame_row(BaselineRow::Kind::only_in_baseline, &baseline[b], nullptr));
  }
  return out;
}

}  // namespace antumbra::app
