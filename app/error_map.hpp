#pragma once
// Error heat maps of `antumbra quality`: where a technique's frame departs from the
// reference, per pixel, on the same signal the metrics use (display luminance, see
// image_metrics.hpp). Signed, so over-shadowing (blue: darker than the reference) and
// light leaks (red: brighter) read apart. Every map of one run shares one scale, so
// two techniques' maps compare by eye.

#include <filesystem>
#include <string>
#include <vector>

#include "antumbra/gpu/image_io.hpp"
#include "image_metrics.hpp"

namespace antumbra::app {

// image - reference per pixel, in display luminance; sizes must agree (throws
// std::invalid_argument).
std::vector<float> signed_error(const FloatImage& reference, const FloatImage& image);

// The colour ramp's end: 1, 2 or 5 times a power of ten at or above the 95th percentile
// of the visible |error|s (>= 1/255) over every map (the worst few pixels saturate
// instead of washing the rest out); 0.001 when no error is visible.
double error_scale(const std::vector<std::vector<float>>& errors);

// RGBA image: blue at -scale, white at 0, red at +scale, clamped beyond.
gpu::HostImage error_heat_map(const std::vector<float>& error, std::uint32_t width,
                              std::uint32_t height, double scale);

struct ErrorMaps {
  double scale = 0.0;  // the ramp's end, shared by every map
  std::vector<std::filesystem::path> files;
};
// Writes DIR/<label>-error.png for each error map (labels[i] names errors[i]), creating
// DIR. Throws std::runtime_error naming the path that cannot be written.
ErrorMaps write_error_maps(const std::filesystem::path& dir, const std::vector<std::string>& labels,
                           const std::vector<std::vector<float>>& errors, std::uint32_t width,
                           std::uint32_t height);

}  // namespace antumbra::app
