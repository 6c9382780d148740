#include "quality_test_support.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <stdexcept>

#include "antumbra/gpu/image_io.hpp"
#include "antumbra/scene/primitives.hpp"
#include "render_test_support.hpp"

namespace antumbra::quality_testing {

std::filesystem::path graph_path(const std::string& name) {
  return render_testing::source_dir() / "data" / "graphs" / (name + ".json");
}

std::filesystem::path quality_data_dir() {
  return render_testing::source_dir() / "tests" / "data" / "quality";
}

fg::GraphDesc graph_for_hdr(const std::filesystem::path& path,
                            const std::vector<std::string>& keep) {
  auto graph = render_testing::load_graph_file(path);
  graph.output = "hdr";
  for (const auto& name : keep) {
    const int index = graph.find_resource(name);
    if (index < 0) throw std::runtime_error(path.string() + " has no resource " + name);
    graph.resources[static_cast<std::size_t>(index)].persistent = true;
  }
  return graph;
}

void set_param(fg::GraphDesc& graph, const std::string& type, const std::string& name,
               const base::Json& value) {
  for (auto& pass : graph.passes) {
    if (pass.type == type) {
      pass.params[name] = value;
      return;
    }
  }
  throw std::runtime_error("graph " + graph.name + " has no pass of type " + type);
}

app::FloatImage read_float_image(runtime::RenderSession& session, const std::string& resource) {
  const auto host = render_testing::read_resource(session, resource);
  app::FloatImage image{host.width, host.height, host.channels == 1 ? 1u : 3u, {}};
  for (std::uint32_t y = 0; y < host.height; ++y) {
    for (std::uint32_t x = 0; x < host.width; ++x) {
      for (std::uint32_t c = 0; c < image.channels; ++c) image.texels.push_back(host.at(x, y, c));
    }
  }
  return image;
}

scene::Scene analytic_scene(const AnalyticSetup& setup) {
  scene::Scene s;
  s.name = "analytic-penumbra";
  s.materials.push_back(matte_grey());

  scene::Mesh plane = scene::make_plane({40.0f, 40.0f});
  plane.name = "receiver";
  plane.update_bounds();
  s.meshes.push_back(std::move(plane));
  scene::Mesh square = scene::make_box({setup.side, 0.02f, setup.side});
  square.name = "occluder";
  square.transform = glm::translate(glm::mat4(1.0f), {0.0f, setup.blocker, 0.0f});
  square.update_bounds();
  s.meshes.push_back(std::move(square));

  scene::PointLight light;
  light.name = "key";
  light.position = {setup.edge_x(), setup.light, 0.0f};
  light.intensity = 20.0f;
  light.range = 12.0f;
  light.size = setup.light_size;
  s.lights.push_back(light);

  const float x = setup.edge_x();
  s.ambient = glm::vec3(0.0f);
  finish_test_scene(s, {x, setup.camera_height, 0.0f}, {x, 0.0f, 0.0f}, {0.0f, 0.0f, -1.0f},
                    setup.fov_y_degrees);
  return s;
}

scene::Material matte_grey() {
  scene::Material grey;
  grey.name = "grey";
  grey.albedo = glm::vec3(0.8f);
  grey.roughness = 1.0f;
  return grey;
}

void finish_test_scene(scene::Scene& s, const glm::vec3& position, const glm::vec3& target,
                       const glm::vec3& up, float fov_y_degrees, float near, float far) {
  s.camera.position = position;
  s.camera.target = target;
  s.camera.up = up;
  s.camera.fov_y_degrees = fov_y_degrees;
  s.camera.near = near;
  s.camera.far = far;
  s.bounds = s.compute_bounds();
}

double transition_width(const std::vector<double>& profile, double low, double high) {
  const double a = low + 0.1 * (high - low);
  const double b = low + 0.9 * (high - low);
  // First crossing of a level, interpolated between samples; -1 when never crossed.
  auto crossing = [&](double level) {
    for (std::size_t i = 1; i < profile.size(); ++i) {
      const double p0 = profile[i - 1];
      const double p1 = profile[i];
      if ((p0 - level) * (p1 - level) <= 0.0 && p0 != p1) {
        return static_cast<double>(i - 1) + (level - p0) / (p1 - p0);
      }
    }
    return -1.0;
  };
  const double xa = crossing(a);
  const double xb = crossing(b);
  if (xa < 0.0 || xb < 0.0) return -1.0;
  return std::abs(xb - xa);
}

std::vector<double> visibility_row(const app::FloatImage& shadowed,
                                   const app::FloatImage& unshadowed) {
  std::vector<double> row;
  const std::uint32_t y = shadowed.height / 2;
  for (std::uint32_t x = 0; x < shadowed.width; ++x) {
    const double lit = unshadowed.at(x, y, 0) + unshadowed.at(x, y, 1) + unshadowed.at(x, y, 2);
    const double got = shadowed.at(x, y, 0) + shadowed.at(x, y, 1) + shadowed.at(x, y, 2);
    row.push_back(lit > 0.0 ? got / lit : 0.0);
  }
  return row;
}

}  // namespace antumbra::quality_testing
