#pragma once
// What the edit session (edit_session.hpp) drives: the running frame graph and the scene it
// renders. The editor's is a runtime::RenderSession (editor_app::SessionRenderer, shared by
// the window and `edit --headless`); tests give one that only compiles, so the session's
// logic is tested without a device or a window (tests/editor/edit_session_test.cpp).

#include <string>
#include <vector>

#include "antumbra/base/diagnostics.hpp"
#include "antumbra/fg/graph_source.hpp"
#include "antumbra/fg/plan.hpp"
#include "antumbra/scene/scene.hpp"

namespace antumbra::editor {

class Renderer {
 public:
  Renderer() = default;
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;
  Renderer(Renderer&&) = delete;
  Renderer& operator=(Renderer&&) = delete;
  virtual ~Renderer() = default;

  // The one load path (fg/graph_source.hpp): reads `source`, applies `edit`, compiles and
  // swaps the graph in. On errors it returns them and the previous graph keeps running.
  virtual base::Diagnostics load_graph(const fg::GraphSource& source,
                                       const fg::GraphEdit& edit) = 0;
  // The running graph's plan; null before a graph was loaded.
  [[nodiscard]] virtual const fg::Plan* plan() const = 0;
  // The files (shaders and their includes) the running graph was built from.
  [[nodiscard]] virtual std::vector<std::string> shader_files() const = 0;
  // The passes of the running graph built from any of `files`.
  [[nodiscard]] virtual std::vector<std::string> passes_reading(
      const std::vector<std::string>& files) const = 0;

  virtual void set_scene(scene::Scene scene) = 0;
  // Lights only: geometry stays uploaded.
  virtual void set_lights(std::vector<scene::PointLight> lights) = 0;
  virtual void set_camera(const scene::Camera& camera) = 0;
  // The size graphs are compiled for; a new one takes effect at the next load_graph().
  [[nodiscard]] virtual fg::Extent2D viewport() const = 0;
  virtual void set_viewport(fg::Extent2D viewport) = 0;
};

}  // namespace antumbra::editor
