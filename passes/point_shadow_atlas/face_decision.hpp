#pragma once
// The compute rasteriser's GPU-side face decision (docs/technique.md, "Receiver-driven
// faces" and "Receiver-driven pages"): copies the frame's shadow data in, optionally marks
// the pages of faces a visible pixel needs (shadow_receivers.comp, from the G-buffer
// depth), then decides per layer which pages are drawn and publishes the graph's
// shadowData (shadow_face_decide.comp). It keeps, per layer, the epoch its pages refer to
// and which of them hold it, so a page skipped for lack of receivers is drawn the first
// frame a receiver appears, and never shown stale. Counters come back
// through a per-slot readback buffer. Every barrier here is on its own buffers.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "antumbra/fgvk/pass.hpp"
#include "antumbra/gpu/hash.hpp"
#include "antumbra/gpu/resources.hpp"
#include "atlas_planner.hpp"
#include "common/pass_support.hpp"
#include "face_decision_interface.h"
#include "shadow_staging.hpp"

namespace antumbra::passes {

// What the decision found on the GPU for one frame (face_decision_interface.h).
struct FaceDecisionStats {
  std::uint64_t frame_index = 0;
  std::uint32_t drawn = 0;
  std::uint32_t cached = 0;
  std::uint32_t receiver_culled = 0;  // visible to the camera, but no visible pixel needs them
  std::uint64_t texels = 0;           // of the drawn pages
  std::uint32_t pages = 0;            // drawn (face_decision_interface.h, kPageSize)
  // The page pool (page_pool_interface.h; all 0 without one).
  struct Pool {
    std::uint32_t pages = 0;    // in the pool
    std::uint32_t kept = 0;     // held by a page some visible pixel needs
    std::uint32_t taken = 0;    // handed to needed pages that had none
    std::uint32_t missing = 0;  // needed pages left without one (they read as lit)
    std::uint32_t evicted = 0;  // of those taken, pages another face held
  } pool;
};

// Pages per side of a face `size` texels wide (face_decision_interface.h, kPageSize), the
// pages a record has room for in the decision's buffers (the atlas's face size), and the
// uints of one bit each.
std::uint32_t pages_per_side(std::uint32_t size);
std::uint32_t page_slots(std::uint32_t atlas_face_size);
std::uint32_t page_words(std::uint32_t atlas_face_size);

// Where the decision puts what is drawn: chunk c's drawn records (the cull's rows) at
// c * chunk_faces, its drawn pages (the resolve's entries) at page_list(c); its resolve's
// dispatch arguments at resolve_args(c) and its cull's at cull_args(c) (the cull covers
// only the drawn records, never the skipped candidates, the resolve only the drawn pages);
// the fill list (far depth for every page not drawn when the contents are unknown) at
// page_list(chunks()), with its resolve arguments at resolve_args(chunks()).
struct DecisionLayout {
  std::uint32_t records = 0;      // candidate records (frame.render_layers)
  std::uint32_t chunk_faces = 1;  // records per chunk
  std::uint32_t face_size = 0;    // the atlas's
  std::uint32_t fill_first = 0;   // 0: no fill; else 1 + the record of layer 0's fill
  std::uint32_t cull_groups = 0;  // the cull's workgroups along the clusters
  bool page_culling = true;       // only the needed pages of a needed face
  float page_reach = 1.0f;        // DecisionPush::page_reach
  // the page pool's pages faces take (0: no pool; page_pool_interface.h); the records'
  // fallback tiles lie in the pages after them (page_tables.h)
  std::uint32_t pool_pages = 0;
  bool pool_fallback = false;  // DecisionPush::pool_fallback
  [[nodiscard]] std::uint32_t chunks() const { return (records + chunk_faces - 1) / chunk_faces; }
  [[nodiscard]] std::uint32_t page_list(std::uint32_t chunk) const {
    return chunks() * chunk_faces + chunk * chunk_faces * page_slots(face_size);
  }
  // List entries for `layers` layers.
  [[nodiscard]] std::uint32_t list_size(std::uint32_t layers) const {
    return page_list(chunks()) + layers * page_slots(face_size);
  }
  // Byte offsets into FaceDecision::args(): a uvec4 pair per chunk (face_decision_interface.h).
  [[nodiscard]] static VkDeviceSize resolve_args(std::uint32_t chunk) {
    return VkDeviceSize{chunk} * 32;
  }
  [[nodiscard]] static VkDeviceSize cull_args(std::uint32_t chunk) {
    return VkDeviceSize{chunk} * 32 + 16;
  }
};

class FaceDecision {
 public:
  // `receivers`: the G-buffer depth is bound and receiver culling is on. `pool`: the faces'
  // pages live in a page pool (page_pool_interface.h), whose tables the decision publishes
  // into the pass's pageTables output.
  void prepare(fgvk::PrepareContext& context, bool receivers, bool pool,
               std::vector<std::string>& shader_files, gpu::Fnv1a64& key);
  // Records everything up to the published shadowData and the resolve lists.
  // `staging`: this frame's shadow data as the planner made it (host-visible).
  void record(fgvk::ExecuteContext& context, const AtlasFrame& frame, const ShadowStaging& staging,
              const DecisionLayout& layout);
  // After the rasterisation: the counters into this slot's readback buffer.
  void finish(fgvk::ExecuteContext& context);
  // The counters of the newest frame whose slot has completed (`slot`'s previous frame
  // when called while recording into it), if any.
  [[nodiscard]] std::optional<FaceDecisionStats> completed(std::uint32_t slot) const;
  // Hands over what the layers hold (a reload that keeps the atlas and its drawing).
  void adopt(FaceDecision& previous);

  [[nodiscard]] bool receivers() const { return receivers_; }
  [[nodiscard]] std::uint32_t last_slot() const { return last_slot_; }
  [[nodiscard]] VkBuffer list() const { return list_; }
  // Page bits of the drawn records (kDecidePages), which the cull reads.
  [[nodiscard]] VkBuffer drawn_pages() const { return drawn_; }
  [[nodiscard]] std::uint32_t page_words() const { return page_words_; }
  [[nodiscard]] VkBuffer args() const { return args_; }
  // The page pool's tables (valid after record; kept across frames).
  [[nodiscard]] VkBuffer tables() const { return tables_; }
  [[nodiscard]] bool pool() const { return pool_; }

 private:
  struct Slot {
    gpu::Buffer requests;  // FaceRequest per layer
    gpu::Buffer readback;  // counters
    gpu::Buffer dirty;     // page bits of the layers with dirty pages (FaceRequest::dirty)
    std::uint64_t frame_index = 0;
    bool written = false;
  };
  void ensure_buffers(fgvk::ExecuteContext& context, std::uint32_t layers,
                      const DecisionLayout& layout);
  void ensure_dirty(fgvk::ExecuteContext& context, Slot& slot, std::size_t layers);
  void write_requests(Slot& slot, const AtlasFrame& frame, const DecisionLayout& layout) const;
  void reset(fgvk::ExecuteContext& context, const ShadowStaging& staging, const AtlasFrame& frame,
             const DecisionLayout& layout);
  void bind(fgvk::ExecuteContext& context, const ComputePipeline& pipeline, Slot& slot);
  void ensure_pool(fgvk::ExecuteContext& context, std::uint32_t layers,
                   const DecisionLayout& layout);
  // shadow_pool_reclaim.comp's two passes, then (after the decision) the publication.
  void reclaim(fgvk::ExecuteContext& context, Slot& slot, shared::DecisionPush push);
  void publish(fgvk::ExecuteContext& context, Slot& slot, const shared::DecisionPush& push);

  bool receivers_ = false;
  ComputePipeline receivers_pipeline_;
  ComputePipeline decide_;
  std::uint32_t layers_ = 0;
  std::uint32_t live_ = 0;  // this frame's AtlasFrame::live_records (at most layers_)
  std::uint32_t list_capacity_ = 0;
  std::uint32_t args_capacity_ = 0;
  gpu::Buffer shadow_in_;  // device copy of the staging data (read by every tile)
  gpu::Buffer needed_;     // page bits per layer
  gpu::Buffer content_;    // per layer: what its pages hold (shadow_face_decide.comp)
  gpu::Buffer drawn_;      // page bits per drawn record
  std::uint32_t page_words_ = 1;
  std::uint32_t page_slots_ = 1;
  std::uint32_t drawn_capacity_ = 0;  // records drawn_ holds
  gpu::Buffer args_;                  // uvec4 pair per chunk (resolve, cull) + the fill's
  gpu::Buffer list_;
  gpu::Buffer stats_;
  bool content_cleared_ = false;  // content_ starts at zero (nothing held)
  std::vector<Slot> slots_;
  std::uint32_t last_slot_ = 0;
  // The page pool (page_pool_interface.h).
  bool pool_ = false;
  ComputePipeline reclaim_;
  ComputePipeline publish_;
  std::uint32_t pool_pages_ = 0;
  std::uint32_t table_words_ = 0;
  gpu::Buffer tables_;       // per record: its page table
  gpu::Buffer table_sizes_;  // per record: the face size its table is laid out for
  gpu::Buffer owners_;       // per pool page
  gpu::Buffer ages_;         // per pool page
  gpu::Buffer order_;        // pool pages in the order they are taken
  gpu::Buffer pool_counters_;
};

}  // namespace antumbra::passes
