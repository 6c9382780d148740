#include "antumbra/editor_app/session_renderer.hpp"

namespace antumbra::editor_app {

base::Diagnostics SessionRenderer::load_graph(const fg::GraphSource& source,
                                              const fg::GraphEdit& edit) {
  return session_.load_graph(source, edit);
}

const fg::Plan* SessionRenderer::plan() const {
  return session_.executor().loaded() ? &session_.executor().plan() : nullptr;
}

std::vector<std::string> SessionRenderer::shader_files() const {
  return session_.executor().shader_files();
}

std::vector<std::string> SessionRenderer::passes_reading(
    const std::vector<std::string>& files) const {
  return session_.executor().passes_reading(files);
}

void SessionRenderer::set_scene(scene::Scene scene) {
  session_.set_scene(std::move(scene));
}

void SessionRenderer::set_lights(std::vector<scene::PointLight> lights) {
  session_.set_lights(std::move(lights));
}

void SessionRenderer::set_camera(const scene::Camera& camera) {
  session_.set_camera(camera);
}

fg::Extent2D SessionRenderer::viewport() const {
  return {session_.viewport().width, session_.viewport().height};
}

void SessionRenderer::set_viewport(fg::Extent2D viewport) {
  session_.set_viewport({viewport.width, viewport.height});
}

}  // namespace antumbra::editor_app
