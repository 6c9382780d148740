#pragma once
// `antumbra edit --headless --script FILE`: the editor's model driven by a JSON script
// instead of a window, rendering every frame through the same runtime::RenderSession. What an
// artist does (move a light, undo, apply the suggested fix, save) and what a tool does
// (replace the graph or a shader on disk, reload) are steps; what must then hold
// (a layer warning this frame, a kept frame after a broken file, a saved file's
// content) are expectations. Used by CI and to measure editor frame times headless.
//
// Script: {"steps": [ {"do": "..."} | {"expect": "..."} , ... ]}, paths relative to the
// script's folder, "$graph" and "$scene" naming the files being edited. See
// docs/edit-script.md for every step.

#include <string>

namespace antumbra::app {

struct EditOptions {
  std::string graph;                 // empty: the default graph
  std::string scene;                 // empty: the default scene
  bool allow_outside_paths = false;  // scene paths outside their file's folder: warnings
  std::string device = "auto";
  bool validation = false;
  int frames = 0;  // > 0: render this many frames after the script, then close
  std::string script;
  bool headless = false;
  std::string size = "1280x720";
  std::string out;            // optional PNG of the last frame
  std::string select;         // window: the light selected at start
  bool frame_log = false;     // window: a line per presented frame
  std::string shots;          // window: F12 screenshots go here
  std::string layout_file;    // window: the layout file instead of the per-user one
  float ui_scale = 0.0f;      // window: > 0 overrides the DPI scale
  std::string layout_report;  // window: JSON of the layout as drawn, on exit
};

int run_edit(const EditOptions& options);

}  // namespace antumbra::app
