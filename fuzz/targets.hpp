#pragma once
// The fuzz targets: one per parser of data made outside Antumbra (docs/robustness.md,
// "Fuzzing"). Each takes any bytes and must end in a result or in diagnostics: never a
// crash, a hang, undefined behaviour or an allocation beyond the documented limits.
// libFuzzer drives them (libfuzzer_entry.cpp, `make fuzz`); tests/fuzz replays the kept
// corpora and regressions, and a fixed number of seeded mutations of them, under the
// ASan + UBSan suite of every CI run.

#include <cstdint>
#include <filesystem>
#include <span>
#include <string_view>

namespace antumbra::fuzz {

using Bytes = std::span<const std::uint8_t>;
using TargetFn = void (*)(Bytes data);

struct Target {
  std::string_view name;  // also the folder of its corpus, regressions and dictionary
  TargetFn run;
};

// Every target, in the order `make fuzz` runs them.
std::span<const Target> targets();
// nullptr when no target has that name.
const Target* find_target(std::string_view name);

// The inputs as the parsers meet them (one file per target).
void graph(Bytes data);        // graph JSON: parse, compile, plan writers
void scene(Bytes data);        // scene JSON: parse, validate, instance
void gltf(Bytes data);         // .gltf (JSON, data URIs) or .glb: the whole import
void edit_script(Bytes data);  // `edit --headless` scripts: parse and check every step
void pfm(Bytes data);          // PFM images of `compare` and `quality`
void png(Bytes data);          // encoded images of glTF materials and scene files

// A folder of this process's own, empty but for what the targets write into it: files a
// target must read from disk go there, and relative paths in them resolve to nothing.
const std::filesystem::path& scratch_folder();

}  // namespace antumbra::fuzz
