#pragma once
// Shared by the quality GPU tests: graphs prepared for read-back of their HDR frame,
// host conversion to the metrics' FloatImage, and the analytic penumbra scene.

#include <filesystem>
#include <string>
#include <vector>

#include "antumbra/fg/graph_desc.hpp"
#include "antumbra/runtime/render_session.hpp"
#include "antumbra/scene/scene.hpp"
#include "image_metrics.hpp"

namespace antumbra::quality_testing {

// The 10%-90% width of a uniformly bright disk's shadow crossing a straight edge, as a
// fraction of the full (0%-100%) penumbra width: the disk covers 10% when the edge is
// 0.687 radii from its centre.
inline constexpr double kDiskTenNinety = 0.6872;

std::filesystem::path graph_path(const std::string& name);  // data/graphs/<name>.json
std::filesystem::path quality_data_dir();                   // tests/data/quality

// The graph with `hdr` as its output (never aliased) and `keep` marked persistent.
fg::GraphDesc graph_for_hdr(const std::filesystem::path& path,
                            const std::vector<std::string>& keep = {});
// Sets a parameter of the first pass of `type` (throws when there is none).
void set_param(fg::GraphDesc& graph, const std::string& type, const std::string& name,
               const base::Json& value);

app::FloatImage read_float_image(runtime::RenderSession& session, const std::string& resource);

// A square occluder (side `side`, thin) at height `blocker` over a large plane at y = 0,
// one point light of radius `light_size` at height `light`, straight above the
// occluder's edge x = side / 2 (so rays to the shadow edge are perpendicular to the
// receiver, where the similar-triangles width is the width on the plane; elsewhere the
// footprint grows by 1 / cos(incidence)); the camera looks straight down at that edge
// from `camera_height`, with no ambient light.
struct AnalyticSetup {
  float side = 2.0f;
  float blocker = 2.0f;
  float light = 4.0f;
  float light_size = 0.25f;
  float camera_height = 1.5f;
  float fov_y_degrees = 60.0f;
  // The occluder edge, the light and the penumbra's centre line share this x.
  [[nodiscard]] float edge_x() const { return 0.5f * side; }
  // Similar triangles, distances from the light: w = (d_r - d_b) * 2 * size / d_b.
  [[nodiscard]] float penumbra_width() const {
    const float d_receiver = light;
    const float d_blocker = light - blocker;
    return (d_receiver - d_blocker) * 2.0f * light_size / d_blocker;
  }
};
scene::Scene analytic_scene(const AnalyticSetup& setup);

// The test scenes' diffuse grey (albedo 0.8, roughness 1).
scene::Material matte_grey();
// A camera at `position` looking at `target` with no ambient light left to set: the
// scene's camera gets `fov_y_degrees`, near 0.05 (or `near`) and far `far`, and the
// scene's bounds are computed from its meshes.
void finish_test_scene(scene::Scene& s, const glm::vec3& position, const glm::vec3& target,
                       const glm::vec3& up, float fov_y_degrees, float near = 0.05f,
                       float far = 20.0f);

// 10%-90% width (in samples, linearly interpolated) of a monotone transition of
// `profile` between its low and high plateaus; negative when none is found.
double transition_width(const std::vector<double>& profile, double low, double high);

// Visibility along the image's middle row: shadowed radiance / unshadowed radiance.
std::vector<double> visibility_row(const app::FloatImage& shadowed,
                                   const app::FloatImage& unshadowed);

}  // namespace antumbra::quality_testing
