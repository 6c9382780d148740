// The docs tables read from bench.json (`antumbra bench`): which scenario and pass fill
// each cell. Scenario names are built as bench_scenarios.cpp builds them at scale 1
// (tests/bench/docs_tables_test.cpp checks that every one is a built-in scenario).
#include <algorithm>
#include <map>

#include "bench_scenarios.hpp"
#include "docs_table_kinds.hpp"

namespace antumbra::app::docs {
namespace {

using Files = std::vector<const ResultFile*>;
using Lines = std::vector<std::string>;
using Rows = std::vector<std::vector<std::string>>;

constexpr const char* kAtlas = "point-shadow-atlas";
constexpr int kLightCounts[] = {16, 64, 256, kDistrictLights};

std::string status_of(const Located& scenario) {
  const auto& value = *scenario.value;
  return value.contains("status") && value["status"].is_string()
             ? value["status"].get<std::string>()
             : "ok";
}

// A scenario that did not measure shows its status instead of numbers.
std::string failed(const Located& scenario) {
  // Appended piece by piece: GCC 12 warns (-Wrestrict, a false positive) on "a" + s.
  std::string text = "*";
  text += status_of(scenario);
  return text + "*";
}

std::string frame_ms(const ResultFile& file, const std::string& name, const std::string& table) {
  const Located s = file.scenario(name, table);
  if (status_of(s) != "ok") return failed(s);
  return fixed(file.number(s, "/frame/medianMs", table), 2);
}

// "12.34 / 10.20": the whole frame / the shadow atlas (every pass of its type).
std::string frame_and_atlas(const ResultFile& file, const std::string& name,
                            const std::string& table) {
  const Located s = file.scenario(name, table);
  if (status_of(s) != "ok") return failed(s);
  const auto atlas = file.pass_median(s, {kAtlas}, table);
  return fixed(file.number(s, "/frame/medianMs", table), 2) + " / " +
         (atlas ? fixed(*atlas, 2) : "-");
}

std::string pass_ms(const ResultFile& file, const std::string& name, const char* type,
                    const std::string& table) {
  const Located s = file.scenario(name, table);
  if (status_of(s) != "ok") return failed(s);
  const auto ms = file.pass_median(s, {type}, table);
  return ms ? fixed(*ms, 2) : "-";
}

// "16 (16), atrium": lights, moving lights and scene of a moving-table scenario.
std::string moving_row_label(const ResultFile& file, const std::string& name,
                             const std::string& table) {
  const Located s = file.scenario(name, table);
  const auto& value = *s.value;
  std::string scene = value.contains("scene") && value["scene"].is_string()
                          ? value["scene"].get<std::string>()
                          : "?";
  scene = scene.substr(0, scene.rfind(".json"));
  return std::to_string(static_cast<int>(file.number(s, "/lights", table))) + " (" +
         std::to_string(static_cast<int>(file.number(s, "/movingLights", table))) + "), " + scene;
}

std::string moving_name(const std::string& technique, int lights, const std::string& suffix) {
  return "moving/" + technique + "/1080p/" + std::to_string(lights) + "l" + suffix;
}

// A table of one bench.json: what its cells hold, its header and rows.
struct BenchTable {
  std::string cells;  // e.g. "whole frame / shadow atlas, ms"
  Lines header;
  Rows rows;
};

// What measured it and what the cells hold, a blank line, the table.
template <BenchTable (*kMake)(const ResultFile&)>
Lines bench_lines(const Files& files, const std::string& link_base) {
  const ResultFile& file = *files.front();
  const BenchTable table = kMake(file);
  const Located root{&file.root(), ""};
  const int frames = static_cast<int>(file.number(root, "/frames", "provenance"));
  const int warmup = static_cast<int>(file.number(root, "/warmup", "provenance"));
  Lines lines{provenance({&file}, link_base) + " GPU medians of " + std::to_string(frames) +
                  " frames after " + std::to_string(warmup) + " warm-up frames; " + table.cells +
                  ".",
              ""};
  const auto markdown = markdown_table(table.header, table.rows);
  lines.insert(lines.end(), markdown.begin(), markdown.end());
  return lines;
}

// Hardware, compute and compute with per-light resolution, for hard and layered SSSS.
BenchTable moving_table(const ResultFile& file) {
  const std::pair<const char*, const char*> techniques[] = {{"hard", "hard"},
                                                            {"layered SSSS 11", "ssss-11"}};
  const std::pair<const char*, const char*> rasters[] = {
      {"hardware", ""}, {"compute", "/compute"}, {"screen", "/compute/screen"}};
  BenchTable table{"whole frame / shadow atlas, ms", {"lights (moving), scene"}, {}};
  for (const auto& [label, technique] : techniques) {
    for (const auto& raster : rasters) {
      table.header.push_back(std::string(raster.first) + ": " + label);
    }
  }
  for (const int lights : kLightCounts) {
    table.rows.push_back({moving_row_label(file, moving_name("hard", lights, ""), "moving")});
    for (const auto& [label, technique] : techniques) {
      for (const auto& raster : rasters) {
        table.rows.back().push_back(
            frame_and_atlas(file, moving_name(technique, lights, raster.second), "moving"));
      }
    }
  }
  return table;
}

BenchTable vis_table(const ResultFile& file) {
  BenchTable table{
      "G-buffer pass of the hard `screen` rows without and with the compute G-buffer; whole "
      "frame / shadow atlas, ms",
      {"lights (moving), scene", "G-buffer: hardware", "G-buffer: compute", "vis: hard",
       "vis: layered SSSS 11"},
      {}};
  for (const int lights : kLightCounts) {
    const std::string screen = moving_name("hard", lights, "/compute/screen");
    const std::string vis = moving_name("hard", lights, "/compute/screen/vis");
    table.rows.push_back(
        {moving_row_label(file, vis, "vis"), pass_ms(file, screen, "gbuffer", "vis"),
         pass_ms(file, vis, "gbuffer", "vis"), frame_and_atlas(file, vis, "vis"),
         frame_and_atlas(file, moving_name("ssss-11", lights, "/compute/screen/vis"), "vis")});
  }
  return table;
}

// One row per graph, its kernels' values side by side ("5 / 11 / 23").
BenchTable table1_table(const ResultFile& file) {
  struct Row {
    std::string graph;
    std::string kernels;
    std::map<unsigned, std::string> frame;  // by height
    std::string atlas;                      // 1080p
  };
  std::vector<Row> rows;
  auto join = [](std::string& to, const std::string& value) {
    to += (to.empty() ? "" : " / ") + value;
  };
  for (const auto& s : builtin_scenarios(1.0)) {
    if (s.table != "table1") continue;
    // 720p comes first for every graph, then 1080p.
    auto it =
        std::find_if(rows.begin(), rows.end(), [&](const Row& r) { return r.graph == s.graph; });
    if (it == rows.end()) it = rows.insert(rows.end(), Row{s.graph, {}, {}, {}});
    join(it->frame[s.height], frame_ms(file, s.name, "table1"));
    if (s.height != 1080) continue;
    if (s.kernel > 0) join(it->kernels, std::to_string(s.kernel));
    join(it->atlas, pass_ms(file, s.name, kAtlas, "table1"));
  }
  BenchTable table{
      "every shadow face redrawn each frame; whole frame at 720p and 1080p and the shadow "
      "atlas at 1080p, ms, one value per kernel",
      {"graph", "kernels", "720p", "1080p", "1080p: shadow atlas"},
      {}};
  for (auto& row : rows) {
    table.rows.push_back({"`" + row.graph + "`", row.kernels.empty() ? "-" : row.kernels,
                          row.frame[720], row.frame[1080], row.atlas});
  }
  return table;
}

// "2.205 / 0.431": the frame and the soft-shadow stage, every pass but the G-buffer, the
// (cached) atlas and tonemap.
std::string frame_and_stage(const ResultFile& file, const std::string& name) {
  const Located s = file.scenario(name, "penumbra");
  if (status_of(s) != "ok") return failed(s);
  const double stage = file.other_passes_median(s, {"gbuffer", kAtlas, "tonemap"}, "penumbra");
  return fixed(file.number(s, "/frame/medianMs", "penumbra"), 3) + " / " + fixed(stage, 3);
}

BenchTable penumbra_table(const ResultFile& file) {
  const std::pair<const char*, const char*> techniques[] = {
      {"PCSS 11", "pcss-11"},
      {"layered SSSS 11, blocker search", "ssss-11"},
      {"layered SSSS 11, min filter", "ssss-min-11"}};
  BenchTable table{
      "whole frame / soft-shadow stage (every pass but G-buffer, shadow atlas and tonemap), ms",
      {"light radius"},
      {}};
  for (const auto& technique : techniques) table.header.emplace_back(technique.first);
  for (const float size : kPenumbraLightSizes) {
    const std::string radius = fixed(size, 2);
    table.rows.push_back({radius + " m"});
    for (const auto& technique : techniques) {
      table.rows.back().push_back(frame_and_stage(
          file, "penumbra/" + std::string(technique.second) + "/1080p/16l/r" + radius + "m"));
    }
  }
  return table;
}

BenchTable dynamic_table(const ResultFile& file) {
  const std::pair<const char*, const char*> techniques[] = {
      {"hard", "hard"}, {"PCSS 11", "pcss-11"}, {"layered SSSS 11", "ssss-11"}};
  BenchTable table{"whole frame / shadow atlas, ms",
                   {"technique", "hardware, static cache", "hardware, no static cache", "compute"},
                   {}};
  for (const auto& [label, technique] : techniques) {
    table.rows.push_back({label});
    for (const char* suffix : {"", "/nocache", "/compute"}) {
      table.rows.back().push_back(frame_and_atlas(
          file, "dynamic/" + std::string(technique) + "/1080p/16l" + suffix, "dynamic"));
    }
  }
  return table;
}

// What textures and cut-outs cost: the atrium against the atrium with alpha-tested screens,
// layered SSSS 11 under 16 moving lights, on every rasteriser variant of the moving table.
BenchTable materials_table(const ResultFile& file) {
  const std::pair<const char*, const char*> rasters[] = {{"hardware", ""},
                                                         {"compute", "/compute"},
                                                         {"screen", "/compute/screen"},
                                                         {"vis", "/compute/screen/vis"}};
  BenchTable table{"whole frame / shadow atlas, ms", {"scene"}, {}};
  for (const auto& raster : rasters) table.header.emplace_back(raster.first);
  for (const char* scene : {"atrium", "atrium-cutouts"}) {
    table.rows.push_back({"`" + std::string(scene) + ".json`"});
    for (const auto& raster : rasters) {
      table.rows.back().push_back(frame_and_atlas(
          file, "materials/ssss-11/1080p/16l/" + std::string(scene) + raster.second, "materials"));
    }
  }
  return table;
}

// "1300 of 2048, 0 missing": the page pool's pages needed against all it has, and those
// needed without a place (the atlas's SHD010 note, "pool").
std::string pool_pages(const ResultFile& file, const std::string& name) {
  const Located s = file.scenario(name, "pages");
  if (status_of(s) != "ok") return failed(s);
  const base::Json* notes = s.value->contains("notes") ? &(*s.value)["notes"] : nullptr;
  if (notes == nullptr || !notes->is_array()) return "-";
  for (std::size_t i = 0; i < notes->size(); ++i) {
    const Located note{&(*notes)[i], s.pointer + "/notes/" + std::to_string(i)};
    if (!note.value->is_object() || note.value->value("code", std::string()) != "SHD010" ||
        !note.value->contains("details") || !(*note.value)["details"].contains("pool")) {
      continue;
    }
    const auto count = [&](const char* key) {
      return std::to_string(
          static_cast<long long>(file.number(note, std::string("/details/pool/") + key, "pages")));
    };
    return count("needed") + " of " + count("pages") + ", " + count("missing") + " missing";
  }
  return "-";
}

// The same lights in squares (no pool): the moving table's atrium row, the "many" rows.
std::string squares_of(const Scenario& paged) {
  if (paged.lights == 16) return "moving/ssss-11/1080p/16l/compute/screen/vis";
  std::string name = paged.name;
  name.replace(0, name.find('/'), "many");
  return name.substr(0, name.rfind('/'));
}

// The page pool (issue: every light shadowed) against the same lights in squares.
BenchTable pages_table(const ResultFile& file) {
  BenchTable table{
      "layered SSSS 11, compute shadow raster, compute G-buffer; whole frame / "
      "shadow atlas, ms",
      {"lights (moving), scene", "page pool", "in squares", "pool: penumbra",
       "pool: tiled lighting", "pool: pages needed"},
      {}};
  for (const auto& s : builtin_scenarios(1.0)) {
    if (s.table != "pages" || s.technique != "ssss") continue;  // against squares' ssss rows
    table.rows.push_back(
        {moving_row_label(file, s.name, "pages"), frame_and_atlas(file, s.name, "pages"),
         frame_and_atlas(file, squares_of(s), "pages"),
         pass_ms(file, s.name, "layered-penumbra", "pages"),
         pass_ms(file, s.name, "tiled-lighting", "pages"), pool_pages(file, s.name)});
  }
  return table;
}

}  // namespace

std::vector<TableKind> bench_table_kinds() {
  return {
      {"moving", 1, "antumbra bench --scenario moving/", bench_lines<moving_table>},
      {"vis", 1, "antumbra bench --scenario moving/", bench_lines<vis_table>},
      {"table1", 1, "antumbra bench --scenario table1/", bench_lines<table1_table>},
      {"penumbra", 1, "antumbra bench --scenario penumbra/", bench_lines<penumbra_table>},
      {"dynamic", 1, "antumbra bench --scenario dynamic/", bench_lines<dynamic_table>},
      {"materials", 1, "antumbra bench --scenario materials/", bench_lines<materials_table>},
      {"pages", 1,
       "antumbra bench --scenario pages/ --scenario many/ --scenario "
       "moving/ssss-11/1080p/16l/compute/screen/vis",
       bench_lines<pages_table>},
  };
}

}  // namespace antumbra::app::docs
