// The comparison with a baseline as `antumbra bench --baseline` writes it: the table on
// stdout, bench_compare.csv, the additions to bench.json and to bench.png.
#include <algorithm>
#include <array>
#include <cstdio>
#include <map>
#include <sstream>

#include "antumbra/editor/atomic_file.hpp"
#include "bench_baseline.hpp"

namespace antumbra::app {
namespace {

std::string fixed(const std::optional<double>& value) {
  if (!value) return "-";
  char text[32];
  std::snprintf(text, sizeof text, "%.3f", *value);
  return text;
}

nlohmann::json json_or_null(const std::optional<double>& value) {
  return value ? nlohmann::json(*value) : nlohmann::json(nullptr);
}

// ">= 5 % and >= 0.02 ms slower", the rule as the summary prints it.
std::string rule_text(const SlowerRule& rule) {
  char text[64];
  std::snprintf(text, sizeof text, ">= %g %% and >= %g ms slower", (rule.ratio - 1.0) * 100.0,
                rule.min_ms);
  return text;
}

// The summary line: what the exit code of `--fail-slower` looks at, then the rest.
std::string summary(const BaselineComparison& c) {
  using Kind = BaselineRow::Kind;
  char text[256];
  std::snprintf(text, sizeof text,
                "%zu of %zu compared rows slower (%s); %zu only in baseline, %zu only in this run, "
                "%zu failed",
                c.slower_count(), c.count(Kind::compared), rule_text(c.rule).c_str(),
                c.count(Kind::only_in_baseline), c.count(Kind::only_in_run), c.count(Kind::failed));
  return text;
}

using Cells = std::array<std::string, 6>;

Cells cells_of(const BaselineRow& row) {
  return {row.scenario,      row.pass,         fixed(row.baseline_ms),
          fixed(row.run_ms), fixed(row.ratio), row_flag(row)};
}

}  // namespace

std::string row_flag(const BaselineRow& row) {
  // A scenario on one side only says so first, then whether it failed there.
  const auto one_side = [&](const char* side, const std::string& status) {
    return row.frame && status != "ok" ? std::string(side) + " (" + status + ")"
                                       : std::string(side);
  };
  switch (row.kind) {
    case BaselineRow::Kind::compared:
      return row.slower ? "slower" : "";
    case BaselineRow::Kind::only_in_baseline:
      return one_side("only in baseline", row.baseline_status);
    case BaselineRow::Kind::only_in_run:
      return one_side("only in this run", row.run_status);
    case BaselineRow::Kind::failed:
      break;
  }
  if (row.baseline_status != "ok" && row.run_status != "ok") {
    return "failed in both: " + row.baseline_status + " / " + row.run_status;
  }
  return row.baseline_status != "ok" ? "failed in baseline: " + row.baseline_status
                                     : "failed in this run: " + row.run_status;
}

void write_comparison_text(std::ostream& out, const BaselineComparison& comparison) {
  std::vector<Cells> lines{{"scenario", "pass", "baseline ms", "this ms", "ratio", "flag"}};
  for (const auto& row : comparison.rows) lines.push_back(cells_of(row));
  std::array<std::size_t, 6> widths{};
  for (const auto& cells : lines) {
    for (std::size_t c = 0; c < cells.size(); ++c) widths[c] = std::max(widths[c], cells[c].size());
  }
  for (const auto& cells : lines) {
    std::string line;
    for (std::size_t c = 0; c < cells.size(); ++c) {
      const std::string pad(widths[c] - cells[c].size(), ' ');
      // Names left-aligned, numbers right-aligned so that their decimal points line up.
      line += c < 2 || c == 5 ? cells[c] + pad : pad + cells[c];
      if (c + 1 < cells.size()) line += "  ";
    }
    line.erase(line.find_last_not_of(' ') + 1);
    out << line << '\n';
  }
  out << summary(comparison) << '\n';
}

void write_comparison_csv(std::ostream& out, const BaselineComparison& comparison) {
  out << "scenario,pass,pass_type,baseline_median_ms,median_ms,ratio,flag\n";
  const auto number = [&](const std::optional<double>& v) {
    if (v) out << *v;
  };
  for (const auto& row : comparison.rows) {
    out << csv_field(row.scenario) << ',' << csv_field(row.pass) << ',' << csv_field(row.type)
        << ',';
    number(row.baseline_ms);
    out << ',';
    number(row.run_ms);
    out << ',';
    number(row.ratio);
    out << ',' << csv_field(row_flag(row)) << '\n';
  }
}

void add_comparison_json(nlohmann::json& bench, const BenchFile& baseline,
                         const BaselineComparison& comparison) {
  auto& scenarios = bench.at("scenarios");
  auto only_in_baseline = nlohmann::json::array();
  for (const auto& row : comparison.rows) {
    if (!row.run_scenario) {
      only_in_baseline.push_back({{"scenario", row.scenario},
                                  {"pass", row.pass},
                                  {"type", row.type},
                                  {"status", row.frame ? row.baseline_status : "ok"},
                                  {"medianMs", json_or_null(row.baseline_ms)}});
      continue;
    }
    auto& scenario = scenarios.at(*row.run_scenario);
    auto& target = row.run_pass ? scenario.at("passes").at(*row.run_pass) : scenario.at("frame");
    target["baselineMedianMs"] = json_or_null(row.baseline_ms);
    target["ratio"] = json_or_null(row.ratio);
    target["slower"] = row.slower;
    if (row.kind != BaselineRow::Kind::compared) target["baselineNote"] = row_flag(row);
  }
  const auto optional = [](const auto& v) { return v ? nlohmann::json(*v) : nlohmann::json(); };
  bench["baseline"] = {{"file", baseline.file},
                       {"commit", baseline.commit},
                       {"device", baseline.device},
                       {"driver", baseline.driver},
                       {"frames", optional(baseline.frames)},
                       {"warmup", optional(baseline.warmup)},
                       {"scale", optional(baseline.scale)},
                       {"slowerRatio", comparison.rule.ratio},
                       {"slowerMinMs", comparison.rule.min_ms},
                       {"slowerCount", comparison.slower_count()},
                       {"onlyInBaseline", only_in_baseline}};
}

void add_comparison_to_chart(StackedChart& chart, const BaselineComparison& comparison) {
  chart.axis_label += "; |: baseline frame median";
  std::map<std::size_t, std::size_t> slower;  // run scenario -> its slower rows
  for (const auto& row : comparison.rows) {
    if (row.slower) ++slower[*row.run_scenario];
  }
  for (const auto& row : comparison.rows) {
    if (!row.frame) continue;
    if (!row.run_scenario) {
      StackedRow only{row.scenario, {}, 0.0, 0.0, row_flag(row)};
      only.marker = row.baseline_ms.value_or(0.0);
      chart.rows.push_back(std::move(only));
      continue;
    }
    auto& target = chart.rows.at(*row.run_scenario);
    if (row.kind != BaselineRow::Kind::compared) {
      target.annotation += " | " + row_flag(row);
      continue;
    }
    target.marker = *row.baseline_ms;
    target.annotation += " | x" + fixed(row.ratio) + " of " + fixed(row.baseline_ms);
    if (const auto n = slower[*row.run_scenario]; n > 0) {
      target.annotation += ", " + std::to_string(n) + " slower";
    }
  }
}

void add_comparison_reports(const std::filesystem::path& dir, const BenchFile& baseline,
                            const BaselineComparison& comparison, nlohmann::json& bench,
                            StackedChart& chart) {
  std::ostringstream csv;
  write_comparison_csv(csv, comparison);
  editor::write_file_atomically(dir / "bench_compare.csv", csv.str());
  add_comparison_json(bench, baseline, comparison);
  add_comparison_to_chart(chart, comparison);
}

}  // namespace antumbra::app
