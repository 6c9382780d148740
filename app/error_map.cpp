#include "error_map.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "plot.hpp"

namespace antumbra::app {
namespace {

constexpr std::array<float, 3> kDarker{0.05f, 0.25f, 0.85f};
constexpr std::array<float, 3> kBrighter{0.85f, 0.08f, 0.05f};

}  // namespace

std::vector<float> signed_error(const FloatImage& reference, const FloatImage& image) {
  if (reference.width != image.width || reference.height != image.height) {
    throw std::invalid_argument("image sizes differ");
  }
  const auto a = display_luminance(reference);
  auto error = display_luminance(image);
  for (std::size_t i = 0; i < error.size(); ++i) error[i] -= a[i];
  return error;
}

double error_scale(const std::vector<std::vector<float>>& errors) {
  std::vector<float> magnitudes;
  // Shadow errors sit on few pixels (edges, penumbrae): a percentile over every pixel
  // would be one of the exact ones. Below one display step a difference is invisible.
  constexpr float kVisible = 1.0f / 255.0f;
  for (const auto& e : errors) {
    for (const float v : e) {
      if (std::fabs(v) >= kVisible) magnitudes.push_back(std::fabs(v));
    }
  }
  if (magnitudes.empty()) return 0.001;
  const auto rank = magnitudes.begin() + static_cast<std::ptrdiff_t>(magnitudes.size() * 95 / 100);
  std::nth_element(magnitudes.begin(), rank, magnitudes.end());
  return nice_tick_step(std::max(static_cast<double>(*rank), 0.001), 1);
}

gpu::HostImage error_heat_map(const std::vector<float>& error, std::uint32_t width,
                              std::uint32_t height, double scale) {
  if (error.size() != std::size_t{width} * height) {
    throw std::invalid_argument("error map size differs from its image");
  }
  gpu::HostImage out{width, height, 4, {}};
  out.texels.reserve(error.size() * 4);
  for (const float e : error) {
    const float t = std::clamp(static_cast<float>(e / scale), -1.0f, 1.0f);
    const auto& end = t < 0.0f ? kDarker : kBrighter;
    const float w = std::fabs(t);
    for (const float c : end) out.texels.push_back(1.0f + w * (c - 1.0f));
    out.texels.push_back(1.0f);
  }
  return out;
}

ErrorMaps write_error_maps(const std::filesystem::path& dir, const std::vector<std::string>& labels,
                           const std::vector<std::vector<float>>& errors, std::uint32_t width,
                           std::uint32_t height) {
  ErrorMaps maps{error_scale(errors), {}};
  std::error_code failure;
  std::filesystem::create_directories(dir, failure);
  if (failure) throw std::runtime_error("cannot create " + dir.string() + ": " + failure.message());
  for (std::size_t i = 0; i < errors.size(); ++i) {
    const auto path = dir / (labels[i] + "-error.png");
    if (!gpu::write_png(path, error_heat_map(errors[i], width, height, maps.scale))) {
      throw std::runtime_error("cannot write " + path.string());
    }
    maps.files.push_back(path);
  }
  return maps;
}

}  // namespace antumbra::app
