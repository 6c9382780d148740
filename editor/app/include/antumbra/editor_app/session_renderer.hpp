#pragma once
// The edit session's renderer (antumbra/editor/renderer.hpp) over a RenderSession: what
// the windowed editor and `edit --headless` both give their editor::EditSession, so the
// two run the same logic on the same device path.

#include "antumbra/editor/renderer.hpp"
#include "antumbra/runtime/render_session.hpp"

namespace antumbra::editor_app {

class SessionRenderer final : public editor::Renderer {
 public:
  explicit SessionRenderer(runtime::RenderSession& session) : session_(session) {}

  [[nodiscard]] runtime::RenderSession& session() { return session_; }

  base::Diagnostics load_graph(const fg::GraphSource& source, const fg::GraphEdit& edit) override;
  [[nodiscard]] const fg::Plan* plan() const override;
  [[nodiscard]] std::vector<std::string> shader_files() const override;
  [[nodiscard]] std::vector<std::string> passes_reading(
      const std::vector<std::string>& files) const override;
  void set_scene(scene::Scene scene) override;
  void set_lights(std::vector<scene::PointLight> lights) override;
  void set_camera(const scene::Camera& camera) override;
  [[nodiscard]] fg::Extent2D viewport() const override;
  void set_viewport(fg::Extent2D viewport) override;

 private:
  runtime::RenderSession& session_;
};

}  // namespace antumbra::editor_app
