// The point-shadow-atlas pass's reports (SHD002, SHD005, SHD010) and the page pool's
// face-size cap from the GPU's counts; the pass itself is in point_shadow_atlas_pass.cpp.
#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "antumbra/base/text.hpp"
#include "pages.h"
#include "point_shadow_atlas_pass.hpp"
#include "pool_fit.hpp"

namespace antumbra::passes {

// A page pool's cap on face size follows the newest GPU counts (pool_fit.hpp), each frame's
// once.
void PointShadowAtlasPass::fit_pool(fgvk::ExecuteContext& context) {
  if (!settings_.page_pool) return;
  const auto gpu = compute_.decision().completed(context.frame.slot);
  if (gpu && gpu->frame_index != pool_fit_frame_) {
    pool_fit_frame_ = gpu->frame_index;
    const FaceDecisionStats::Pool& p = gpu->pool;
    std::uint32_t largest = 0;  // the largest face the last frame gave a light
    for (const ShadowLight& light : planner_.last().lights) {
      if (light.params.z >= 0.0f) {
        largest = std::max(largest, static_cast<std::uint32_t>(light.projection.y));
      }
    }
    pool_fit_.update(
        {.frame = gpu->frame_index,
         .pages = p.pages,
         .needed = p.kept + p.taken + p.missing,
         .missing = p.missing},
        {.index = context.frame.frame_index, .largest = largest, .atlas = settings_.face_size});
  }
  settings_.pool_cap = pool_fit_.cap();
}

// SHD002: lights without faces (no face records left, or no room even for the smallest
// squares); SHD005: lights whose faces are drawn smaller than they want (the atlas is full).
void PointShadowAtlasPass::report_fit(fgvk::ExecuteContext& context, const AtlasFrame& frame) {
  // Appended, not operator+(string&&, ...): GCC 12 warns falsely (-Wrestrict).
  std::string where = "; the shadowData buffer holds ";
  where += std::to_string(settings_.records);
  where += " face records (6 per point light, 1 per spot, 1-4 for the sun), the atlas ";
  where += std::to_string(settings_.layers);
  where += " layers of ";
  where += std::to_string(settings_.face_size);
  where += "^2 texels";
  const base::Json sizes{{"records", settings_.records},
                         {"layers", settings_.layers},
                         {"layersUsed", frame.stats.layers_used},
                         {"texelsHeld", frame.stats.texels_held}};
  if (!frame.unshadowed.empty()) {
    base::Json details = sizes;
    details["lights"] = frame.unshadowed;
    std::string message = std::to_string(frame.unshadowed.size());
    message += " shadow-casting light(s) do not fit and cast no shadows: ";
    message += base::name_list(frame.unshadowed);
    message += where;
    context.report.add({context.pass.name, codes::shadow_atlas::kLightsUnshadowed,
                        base::Severity::warning, message, details});
  }
  if (!frame.degraded.empty()) {
    base::Json lights = base::Json::array();
    std::vector<std::string> names;
    for (const DegradedLight& d : frame.degraded) {
      lights.push_back({{"light", d.name}, {"wanted", d.wanted}, {"given", d.given}});
      std::string name = d.name;
      name += ' ';
      name += std::to_string(d.given);
      name += " of ";
      name += std::to_string(d.wanted);
      names.push_back(std::move(name));
    }
    base::Json details = sizes;
    details["lights"] = lights;
    std::string message = std::to_string(frame.degraded.size());
    if (settings_.page_pool) {
      details["poolCap"] = settings_.pool_cap;
      message += " light(s) have smaller faces than they want, the page pool missing pages the ";
      message += "view needs at their size (faces at most ";
      message += std::to_string(settings_.pool_cap);
      message += " texels until it holds them; texels per side, given of wanted): ";
    } else {
      message += " light(s) have smaller faces than they want, the atlas being full (texels per ";
      message += "side, given of wanted): ";
    }
    message += base::name_list(names);
    message += where;
    context.report.add({context.pass.name, codes::shadow_atlas::kFacesDegraded,
                        base::Severity::note, message, details});
  }
}

fgvk::PassMessage PointShadowAtlasPass::face_stats(
    const std::string& pass, const std::optional<FaceDecisionStats>& gpu) const {
  const AtlasStats& s = planner_.last().stats;
  const bool compute = params_.rasterizer == ShadowRasterizer::compute;
  base::Json details{{"total", s.total},
                     {"culled", s.culled},
                     {"culledByFrustum", s.culled},
                     {"culledByReceivers", 0},
                     {"rendered", s.rendered},
                     {"cached", s.cached},
                     {"texels", s.texels},
                     {"layered", layered_},
                     {"receiverCulling", settings_.gpu_decides},
                     {"faceSizes", face_sizes()},
                     {"dynamic", s.dynamic},
                     {"dynamicPages", s.dynamic_pages},
                     {"overStaticCache", s.over_cache},
                     {"deferred", s.deferred},
                     {"forced", s.forced},
                     {"stalestFrames", s.stalest},
                     {"staticCacheBytes", static_cache_.bytes()},
                     {"rasterizer", compute ? "compute" : "hardware"}};
  if (compute) {
    // Which shader variant the clusters take (compute_raster.hpp): scenes without cut
    // materials have every opaque cluster on the solid path.
    const ComputeRasterStats& c = compute_.stats();
    details["clusters"] = {{"total", c.clusters},
                           {"solid", c.solid_clusters},
                           {"cut", c.cut_clusters},
                           {"translucent", c.translucent_clusters},
                           {"cutPipelineBuilt", compute_.cut_pipeline_built()}};
  }
  std::string text = "shadow faces: " + std::to_string(s.total) + " total, " +
                     std::to_string(s.culled) + " culled, " + std::to_string(s.rendered) +
                     " rendered, " + std::to_string(s.cached) + " cached";
  if (s.dynamic > 0 || s.over_cache > 0) {
    text += " (" + std::to_string(s.dynamic) + " for moved dynamic meshes, " +
            std::to_string(s.over_cache) + " over the static cache)";
  }
  if (s.deferred > 0 || s.forced > 0) {
    text += "; budget: " + std::to_string(s.deferred) + " waiting (at most " +
            std::to_string(s.stalest) + " frames behind), " + std::to_string(s.forced) + " past it";
  }
  if (settings_.gpu_decides) {
    // Drawn or not is the GPU's decision: its counts, of the frame they belong to.
    const FaceDecisionStats g = gpu.value_or(FaceDecisionStats{});
    const std::uint32_t culled = s.culled + g.receiver_culled;
    details["culled"] = culled;
    details["culledByReceivers"] = g.receiver_culled;
    details["rendered"] = g.drawn;
    details["cached"] = g.cached;
    details["texels"] = g.texels;
    details["pages"] = g.pages;
    details["receiverPages"] = params_.receiver_pages;
    details["statsFrame"] = gpu ? base::Json(g.frame_index) : base::Json(nullptr);
    if (settings_.page_pool) details["pool"] = pool_details(g.pool);
    text = "shadow faces: " + std::to_string(s.total) + " total, " + std::to_string(culled) +
           " culled (" + std::to_string(g.receiver_culled) + " without a visible receiver), " +
           std::to_string(g.drawn) + " rendered (" + std::to_string(g.pages) + " pages), " +
           std::to_string(g.cached) + " cached" +
           (gpu ? " (GPU counts of frame " + std::to_string(g.frame_index) + ")"
                : " (GPU counts pending)");
    if (s.dynamic_pages > 0) {
      text += "; this frame " + std::to_string(s.dynamic_pages) +
              " pages sent to be redrawn where dynamic meshes moved";
    }
  }
  return {pass, codes::shadow_atlas::kFaceStats, base::Severity::note, text, std::move(details)};
}

// The pages faces take: the atlas's, less the fallback tiles' at the end (pool_fit.hpp;
// the compiler's FG033 keeps some).
std::uint32_t PointShadowAtlasPass::pool_pages() const {
  if (!settings_.page_pool) return 0;
  const std::uint32_t side = settings_.face_size >> shared::kPageShift;
  const std::uint32_t all = settings_.layers * side * side;
  return all - std::min(all, pool_reserve());
}

// Pages at the pool's end for the records' fallback tiles (pageFallback; pool_fit.hpp).
std::uint32_t PointShadowAtlasPass::pool_reserve() const {
  return settings_.page_pool && params_.page_fallback ? pool_fallback_pages(settings_.records) : 0u;
}

// SHD010's `pool`: the page pool's pages and what the GPU did with them (face_decision.hpp).
base::Json PointShadowAtlasPass::pool_details(const FaceDecisionStats::Pool& pool) const {
  const std::uint64_t page_bytes = std::uint64_t{shared::kPageSize} * shared::kPageSize * 4;
  const std::uint32_t fallback = pool_reserve();
  return base::Json::object({{"pages", pool.pages},
                             {"fallbackPages", fallback},
                             {"bytes", (std::uint64_t{pool.pages} + fallback) * page_bytes},
                             {"needed", pool.kept + pool.taken + pool.missing},
                             {"kept", pool.kept},
                             {"taken", pool.taken},
                             {"evicted", pool.evicted},
                             {"missing", pool.missing}});
}

// How many shadowed lights have each face size (per-light resolution), e.g. {"256": 3}.
base::Json PointShadowAtlasPass::face_sizes() const {
  std::map<std::uint32_t, std::uint32_t> counts;
  for (const ShadowLight& light : planner_.last().lights) {
    if (light.params.z >= 0.0f) ++counts[static_cast<std::uint32_t>(light.projection.y)];
  }
  base::Json out = base::Json::object();
  for (const auto& [size, n] : counts) out[std::to_string(size)] = n;
  return out;
}

void PointShadowAtlasPass::collect(fgvk::FrameReport& report) {
  if (params_.rasterizer != ShadowRasterizer::compute) return;
  const auto gpu = compute_.decision().completed(compute_.decision().last_slot());
  if (gpu) {
    report.replace(face_stats(name_, gpu));
    return;
  }
  // GPU counts still pending: the note made while recording stays, but whether the CUT
  // variant exists is only known once the frame has been recorded.
  for (const fgvk::PassMessage& m : report.messages()) {
    if (m.pass != name_ || m.code != codes::shadow_atlas::kFaceStats) continue;
    fgvk::PassMessage updated = m;
    if (updated.details.contains("clusters")) {
      updated.details["clusters"]["cutPipelineBuilt"] = compute_.cut_pipeline_built();
    }
    report.replace(std::move(updated));
    return;
  }
}

}  // namespace antumbra::passes
