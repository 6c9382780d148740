#include "image_metrics.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace antumbra::app {
namespace {

constexpr int kSsimRadius = 5;  // 11x11 window
constexpr double kSsimSigma = 1.5;
constexpr double kC1 = 0.01 * 0.01;
constexpr double kC2 = 0.03 * 0.03;

float byte_swapped(float value) {
  std::uint32_t bits = 0;
  std::memcpy(&bits, &value, sizeof bits);
  bits = (bits >> 24) | ((bits >> 8) & 0xFF00u) | ((bits << 8) & 0xFF0000u) | (bits << 24);
  std::memcpy(&value, &bits, sizeof bits);
  return value;
}

// Separable Gaussian blur whose weights are cut at the border and renormalised.
std::vector<double> blur(const std::vector<double>& in, std::uint32_t width, std::uint32_t height) {
  std::array<double, 2 * kSsimRadius + 1> kernel{};
  for (int i = -kSsimRadius; i <= kSsimRadius; ++i) {
    kernel[static_cast<std::size_t>(i) + kSsimRadius] =
        std::exp(-(i * i) / (2.0 * kSsimSigma * kSsimSigma));
  }
  const int w = static_cast<int>(width);
  const int h = static_cast<int>(height);
  auto pass = [&](const std::vector<double>& src, bool horizontal) {
    std::vector<double> dst(src.size());
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        double sum = 0.0;
        double weights = 0.0;
        for (int i = -kSsimRadius; i <= kSsimRadius; ++i) {
          const int sx = horizontal ? x + i : x;
          const int sy = horizontal ? y : y + i;
          if (sx < 0 || sy < 0 || sx >= w || sy >= h) continue;
          const double k = kernel[static_cast<std::size_t>(i) + kSsimRadius];
          sum += k * src[static_cast<std::size_t>(sy) * width + static_cast<std::size_t>(sx)];
          weights += k;
        }
        dst[static_cast<std::size_t>(y) * width + static_cast<std::size_t>(x)] = sum / weights;
      }
    }
    return dst;
  };
  return pass(pass(in, true), false);
}

}  // namespace

std::optional<FloatImage> decode_pfm(std::span<const std::uint8_t> bytes, const std::string& name,
                                     std::string& error) {
  // The header is text: "PF"/"Pf", width, height and scale separated by whitespace, then
  // one whitespace character; at most a few dozen bytes, so a bounded prefix is parsed.
  const std::size_t prefix = std::min<std::size_t>(bytes.size(), 256);
  std::istringstream header(std::string(reinterpret_cast<const char*>(bytes.data()), prefix));
  std::string magic;
  long long width = 0;
  long long height = 0;
  double scale = 0.0;
  header >> magic >> width >> height >> scale;
  if (!header || (magic != "PF" && magic != "Pf")) {
    error = name + ": not a PFM file (expected a \"PF\" or \"Pf\" header)";
    return std::nullopt;
  }
  if (width <= 0 || height <= 0 || width > kMaxPfmSide || height > kMaxPfmSide || !(scale != 0.0) ||
      !std::isfinite(scale)) {
    error = name + ": bad PFM header (size " + std::to_string(width) + "x" +
            std::to_string(height) + ", scale must be finite and non-zero)";
    return std::nullopt;
  }
  const auto pixels = static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height);
  if (pixels > kMaxPfmPixels) {
    error = name + ": PFM of " + std::to_string(width) + "x" + std::to_string(height) +
            " pixels is over the limit of " + std::to_string(kMaxPfmPixels) +
            " pixels (docs/robustness.md, \"Limits\")";
    return std::nullopt;
  }
  // The single whitespace character after the scale; the rows start after it.
  if (header.get() == std::char_traits<char>::eof()) {
    error = name + ": truncated PFM (no data after the header)";
    return std::nullopt;
  }
  const auto data_start = static_cast<std::size_t>(header.tellg());
  FloatImage image;
  image.width = static_cast<std::uint32_t>(width);
  image.height = static_cast<std::uint32_t>(height);
  image.channels = magic == "PF" ? 3 : 1;
  const std::size_t row_floats = std::size_t{image.width} * image.channels;
  // Every row is there before anything is allocated: a header alone cannot ask for memory.
  const std::size_t rows_present = (bytes.size() - data_start) / (row_floats * 4);
  if (rows_present < image.height) {
    error = name + ": truncated PFM (" + std::to_string(rows_present) + " of " +
            std::to_string(image.height) + " rows)";
    return std::nullopt;
  }
  image.texels.resize(row_floats * image.height);
  // PFM rows run bottom to top; keep ours top row first like gpu::HostImage.
  for (std::uint32_t row = 0; row < image.height; ++row) {
    float* dst = image.texels.data() + (image.height - 1 - row) * row_floats;
    std::memcpy(dst, bytes.data() + data_start + std::size_t{row} * row_floats * 4, row_floats * 4);
  }
  const bool file_little = scale < 0.0;
  if (file_little != (std::endian::native == std::endian::little)) {
    for (float& v : image.texels) v = byte_swapped(v);
  }
  return image;
}

std::optional<FloatImage> read_pfm(const std::filesystem::path& path, std::string& error) {
  errno = 0;
  std::ifstream file(path, std::ios::binary);
  if (!file) {
    const int reason = errno;
    error = "cannot open " + path.string() + ": " +
            (reason != 0 ? std::strerror(reason) : "unknown reason");
    return std::nullopt;
  }
  // No more than the largest image the limits allow (and its header) is read.
  const std::size_t most = kMaxPfmPixels * 3 * sizeof(float) + 256;
  std::vector<std::uint8_t> bytes;
  std::array<char, 1 << 16> chunk{};
  while (file && bytes.size() <= most) {
    file.read(chunk.data(), chunk.size());
    const auto got = static_cast<std::size_t>(file.gcount());
    bytes.insert(bytes.end(), chunk.begin(), chunk.begin() + static_cast<std::ptrdiff_t>(got));
  }
  return decode_pfm(bytes, path.string(), error);
}

bool write_pfm(const std::filesystem::path& path, const FloatImage& image) {
  std::ofstream file(path, std::ios::binary);
  if (!file) return false;
  const bool grey = image.channels == 1;
  const std::uint32_t out = grey ? 1 : 3;
  const float scale = std::endian::native == std::endian::little ? -1.0f : 1.0f;
  file << (grey ? "Pf" : "PF") << "\n"
       << image.width << " " << image.height << "\n"
       << (scale < 0 ? "-1.0" : "1.0") << "\n";
  std::vector<float> row;
  for (std::uint32_t y = image.height; y-- > 0;) {
    row.clear();
    for (std::uint32_t x = 0; x < image.width; ++x) {
      for (std::uint32_t c = 0; c < out; ++c) row.push_back(image.at(x, y, c));
    }
    file.write(reinterpret_cast<const char*>(row.data()),
               static_cast<std::streamsize>(row.size() * sizeof(float)));
  }
  return static_cast<bool>(file);
}

std::vector<float> display_luminance(const FloatImage& image) {
  const std::size_t pixels = std::size_t{image.width} * image.height;
  std::vector<float> out(pixels);
  for (std::size_t i = 0; i < pixels; ++i) {
    const float* t = image.texels.data() + i * image.channels;
    float y = image.channels >= 3 ? 0.2126f * t[0] + 0.7152f * t[1] + 0.0722f * t[2] : t[0];
    if (std::isnan(y)) y = 0.0f;
    out[i] = std::clamp(y, 0.0f, 1.0f);
  }
  return out;
}

std::string_view to_string(MaskRegion region) {
  switch (region) {
    case MaskRegion::all:
      return "all";
    case MaskRegion::penumbra:
      return "penumbra";
    case MaskRegion::overlap:
      return "overlap";
    case MaskRegion::silhouette:
      return "silhouette";
  }
  return "all";
}

std::optional<MaskRegion> parse_mask_region(std::string_view name) {
  if (name == "all") return MaskRegion::all;
  if (name == "penumbra") return MaskRegion::penumbra;
  if (name == "overlap") return MaskRegion::overlap;
  if (name == "silhouette") return MaskRegion::silhouette;
  return std::nullopt;
}

std::vector<std::uint8_t> region_mask(MaskRegion region, const FloatImage* mask,
                                      std::size_t pixels) {
  std::vector<std::uint8_t> selected(pixels, 1);
  if (region == MaskRegion::all) return selected;
  if (mask == nullptr) throw std::invalid_argument("a penumbra/overlap region needs a mask image");
  if (region == MaskRegion::silhouette) {
    if (mask->channels < 2) throw std::invalid_argument("the silhouette region needs channel 1");
    for (std::size_t i = 0; i < pixels; ++i) {
      selected[i] = mask->texels[i * mask->channels + 1] >= 1.0f ? 1 : 0;
    }
    return selected;
  }
  const float threshold = region == MaskRegion::penumbra ? 1.0f : 2.0f;
  for (std::size_t i = 0; i < pixels; ++i) {
    selected[i] = mask->texels[i * mask->channels] >= threshold ? 1 : 0;
  }
  return selected;
}

std::vector<std::uint8_t> silhouette_mask(const FloatImage& depth, float near, float far,
                                          int radius, float relative_jump) {
  const std::uint32_t w = depth.width;
  const std::uint32_t h = depth.height;
  std::vector<float> z(std::size_t{w} * h);
  for (std::uint32_t y = 0; y < h; ++y) {
    for (std::uint32_t x = 0; x < w; ++x) {
      // Inverse of d = far (z - near) / (z (far - near)).
      const double d = std::clamp(static_cast<double>(depth.at(x, y, 0)), 0.0, 1.0);
      z[std::size_t{y} * w + x] =
          static_cast<float>(double(near) * far / std::max(far - d * (far - near), 1e-9));
    }
  }
  std::vector<std::uint8_t> edge(z.size(), 0);
  const auto jump = [&](std::size_t a, std::size_t b) {
    return std::abs(z[a] - z[b]) > relative_jump * std::min(z[a], z[b]);
  };
  for (std::uint32_t y = 0; y < h; ++y) {
    for (std::uint32_t x = 0; x < w; ++x) {
      const std::size_t i = std::size_t{y} * w + x;
      if (x + 1 < w && jump(i, i + 1)) edge[i] = edge[i + 1] = 1;
      if (y + 1 < h && jump(i, i + w)) edge[i] = edge[i + w] = 1;
    }
  }
  std::vector<std::uint8_t> out(z.size(), 0);
  for (std::uint32_t y = 0; y < h; ++y) {
    for (std::uint32_t x = 0; x < w; ++x) {
      if (edge[std::size_t{y} * w + x] == 0) continue;
      const int y0 = std::max(0, static_cast<int>(y) - radius);
      const int y1 = std::min(static_cast<int>(h) - 1, static_cast<int>(y) + radius);
      const int x0 = std::max(0, static_cast<int>(x) - radius);
      const int x1 = std::min(static_cast<int>(w) - 1, static_cast<int>(x) + radius);
      for (int yy = y0; yy <= y1; ++yy) {
        for (int xx = x0; xx <= x1; ++xx) out[static_cast<std::size_t>(yy) * w + xx] = 1;
      }
    }
  }
  return out;
}

std::vector<double> ssim_map(const std::vector<float>& a, const std::vector<float>& b,
                             std::uint32_t width, std::uint32_t height) {
  const std::size_t n = a.size();
  std::vector<double> va(n), vb(n), aa(n), bb(n), ab(n);
  for (std::size_t i = 0; i < n; ++i) {
    va[i] = a[i];
    vb[i] = b[i];
    aa[i] = double(a[i]) * a[i];
    bb[i] = double(b[i]) * b[i];
    ab[i] = double(a[i]) * b[i];
  }
  const auto mu_a = blur(va, width, height);
  const auto mu_b = blur(vb, width, height);
  const auto e_aa = blur(aa, width, height);
  const auto e_bb = blur(bb, width, height);
  const auto e_ab = blur(ab, width, height);
  std::vector<double> map(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double var_a = std::max(0.0, e_aa[i] - mu_a[i] * mu_a[i]);
    const double var_b = std::max(0.0, e_bb[i] - mu_b[i] * mu_b[i]);
    const double cov = e_ab[i] - mu_a[i] * mu_b[i];
    map[i] = ((2.0 * mu_a[i] * mu_b[i] + kC1) * (2.0 * cov + kC2)) /
             ((mu_a[i] * mu_a[i] + mu_b[i] * mu_b[i] + kC1) * (var_a + var_b + kC2));
  }
  return map;
}

Metrics compute_metrics(const std::vector<float>& a, const std::vector<float>& b,
                        const std::vector<double>& ssim,
                        const std::vector<std::uint8_t>& selected) {
  Metrics m;
  double squared = 0.0;
  double ssim_sum = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (selected[i] == 0) continue;
    const double d = double(a[i]) - double(b[i]);
    squared += d * d;
    ssim_sum += ssim[i];
    ++m.pixels;
  }
  if (m.pixels == 0) {
    m.rmse = m.psnr = m.ssim = std::numeric_limits<double>::quiet_NaN();
    return m;
  }
  const double mse = squared / static_cast<double>(m.pixels);
  m.rmse = std::sqrt(mse);
  m.psnr = mse > 0.0 ? std::min(kPsnrCap, 10.0 * std::log10(1.0 / mse)) : kPsnrCap;
  m.ssim = ssim_sum / static_cast<double>(m.pixels);
  return m;
}

std::vector<Comparison> compare_images(const FloatImage& a, const FloatImage& b,
                                       const FloatImage* mask,
                                       const std::vector<MaskRegion>& regions) {
  auto size = [](const FloatImage& i) {
    return std::to_string(i.width) + "x" + std::to_string(i.height);
  };
  if (a.width != b.width || a.height != b.height) {
    throw std::invalid_argument("image sizes differ: " + size(a) + " vs " + size(b));
  }
  if (mask != nullptr && (mask->width != a.width || mask->height != a.height)) {
    throw std::invalid_argument("mask size " + size(*mask) + " differs from the images' " +
                                size(a));
  }
  const auto la = display_luminance(a);
  const auto lb = display_luminance(b);
  const auto ssim = ssim_map(la, lb, a.width, a.height);
  std::vector<Comparison> out;
  out.reserve(regions.size());
  for (const MaskRegion region : regions) {
    out.push_back({region, compute_metrics(la, lb, ssim, region_mask(region, mask, la.size()))});
  }
  return out;
}

}  // namespace antumbra::app
