#pragma once
// `render --watch`: after the first frame, polls the graph, the scene and every shader
// file (with includes) and reloads what changed as a transaction: a change is parsed,
// validated and compiled beside the running state and swapped in only when fully
// valid; anything invalid prints its diagnostics and leaves the last good graph,
// pipelines and scene rendering. Each successful reload writes a new image.

#include <string>

#include "antumbra/runtime/render_session.hpp"
#include "antumbra/scene/scene_file.hpp"

namespace antumbra::runtime {

struct WatchOptions {
  std::string graph_path;
  std::string scene_path;
  std::string output;  // --output override ("" = the graph's own output)
  std::string out;     // image written after each successful reload
  double seconds = 0;  // stop after this long (0 = until interrupted)
  double poll_ms = 100;
  scene::SceneFileOptions scene_options;  // for every reload of the scene
};

// Returns the process exit code (0 when the loop ends by time).
int run_watch_loop(RenderSession& session, const WatchOptions& options);

}  // namespace antumbra::runtime
