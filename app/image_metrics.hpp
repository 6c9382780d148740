#pragma once
// Image-quality metrics of `antumbra compare` and the quality tests: how far a shadow
// technique's HDR frame is from the reference's, over all pixels or over penumbra /
// overlapping-penumbra pixels picked by a mask.
//
// Every metric is computed on one signal per pixel: the Rec. 709 luminance of the HDR
// radiance (0.2126 R + 0.7152 G + 0.0722 B; a one-channel image is its own luminance),
// clamped to [0, 1]. The clamp plays the part of a display: differences above white are
// invisible and must not dominate, and it fixes the peak for PSNR at 1.0.
//  - RMSE = sqrt(mean((a - b)^2)) over the selected pixels;
//  - PSNR = 10 log10(1 / MSE) dB, capped at kPsnrCap (identical images);
//  - SSIM (Wang et al. 2004) with an 11x11 Gaussian window (sigma 1.5), C1 = 0.01^2,
//    C2 = 0.03^2; the window is cut at the image border and its weights renormalised, so
//    every pixel has an SSIM value; the reported SSIM is the mean over selected pixels.
// Masks: `penumbra` selects pixels whose mask value (channel 0, e.g. the reference's
// penumbraCount) is >= 1, `overlap` those with >= 2; `silhouette` those whose channel 1
// is >= 1 (silhouette_mask: pixels near a depth discontinuity, where a technique that
// filters or upsamples across depth edges shows seams); `all` selects every pixel.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace antumbra::app {

inline constexpr double kPsnrCap = 100.0;
// What a PFM may hold (docs/robustness.md, "Limits"): 64 Mpixel, 768 MiB of RGB floats.
inline constexpr long long kMaxPfmSide = 65536;
inline constexpr std::uint64_t kMaxPfmPixels = std::uint64_t{1} << 26;

// Float image, row-major with the top row first, `channels` floats per texel.
struct FloatImage {
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::uint32_t channels = 3;
  std::vector<float> texels;

  [[nodiscard]] float at(std::uint32_t x, std::uint32_t y, std::uint32_t c) const {
    return texels[(std::size_t{y} * width + x) * channels + c];
  }
};

// Reads a PFM as gpu::write_pfm writes it ("PF" RGB or "Pf" grey, rows bottom to top,
// negative scale = little endian; big endian files are accepted too) and returns it top
// row first. On failure returns nullopt and sets `error`.
std::optional<FloatImage> read_pfm(const std::filesystem::path& path, std::string& error);
// The same from the file's bytes; `name` starts the error. Images over kMaxPfmSide on a side
// or kMaxPfmPixels in all are refused before anything is allocated, and so are files
// shorter than their header says.
std::optional<FloatImage> decode_pfm(std::span<const std::uint8_t> bytes, const std::string& name,
                                     std::string& error);
// Writes `image` (1 or 3 channels; 4 channels drop alpha) like gpu::write_pfm.
bool write_pfm(const std::filesystem::path& path, const FloatImage& image);

// Luminance clamped to [0, 1], one value per pixel.
std::vector<float> display_luminance(const FloatImage& image);

enum class MaskRegion { all, penumbra, overlap, silhouette };
std::string_view to_string(MaskRegion region);
std::optional<MaskRegion> parse_mask_region(std::string_view name);

// Per-pixel selection of a region: all pixels, or the mask thresholds above.
std::vector<std::uint8_t> region_mask(MaskRegion region, const FloatImage* mask,
                                      std::size_t pixels);

// 1 for pixels within `radius` pixels (Chebyshev) of a depth discontinuity: neighbouring
// linear depths that differ by more than `relative_jump` of the nearer one. `depth` holds
// perspectiveRH_ZO window depths (scene::Camera) of a camera with `near` and `far`; the
// far plane (depth 1, the sky) counts as a surface at `far`.
std::vector<std::uint8_t> silhouette_mask(const FloatImage& depth, float near, float far,
                                          int radius = 2, float relative_jump = 0.1f);

struct Metrics {
  std::size_t pixels = 0;  // selected pixels; the values below are NaN when 0
  double rmse = 0.0;
  double psnr = 0.0;
  double ssim = 0.0;
};

// SSIM value of every pixel of two luminance images of width x height.
std::vector<double> ssim_map(const std::vector<float>& a, const std::vector<float>& b,
                             std::uint32_t width, std::uint32_t height);

// Metrics over the pixels where `selected` is non-zero. Sizes must agree (the caller
// checks the images).
Metrics compute_metrics(const std::vector<float>& a, const std::vector<float>& b,
                        const std::vector<double>& ssim, const std::vector<std::uint8_t>& selected);

// Everything `compare` reports for one pair of images.
struct Comparison {
  MaskRegion region = MaskRegion::all;
  Metrics metrics;
};
// Compares a and b (same size, checked: throws std::invalid_argument otherwise) over each
// of `regions` (mask required for penumbra/overlap; same size as a).
std::vector<Comparison> compare_images(const FloatImage& a, const FloatImage& b,
                                       const FloatImage* mask,
                                       const std::vector<MaskRegion>& regions);

}  // namespace antumbra::app
