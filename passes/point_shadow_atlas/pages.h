// Pages of the compute rasteriser's faces, shared by the face decision
// (face_decision_interface.h) and the rasteriser (compute_raster_interface.h), valid GLSL
// and C++ (docs/technique.md, "Receiver-driven pages").
#ifndef ANTUMBRA_PAGES_H
#define ANTUMBRA_PAGES_H

#include "../interface/shared/glsl_cpp.h"
#include "../interface/shared/page_tables.h"

ANTUMBRA_SHARED_BEGIN

// Pages (docs/technique.md, "Receiver-driven pages"): a face is drawn in square pages of
// kPageSize texels (its last row and column of pages cut at its edge; one page for a face
// no larger), the compute rasteriser's screen regions (compute_raster_interface.h), and
// only the pages some visible pixel may read are drawn. A pixel needs every page within
// kPageMargin texels of where it falls in a face (the PCF and PCSS kernels; the derived
// maps' filters: a min filter of radius 8 over texels 8 atlas texels wide reads up to
// 8 x (8 + 1) = 72 away) plus the blocker searches' reach, which grows with the light's
// size (shadow_receivers.comp). When a face is drawn, its pages nobody needs that hold an
// older epoch are filled with far depth, so a lookup reaching past the needed pages
// reads "no blocker", never another frame's or another face's depth. Each layer keeps a
// bit per page (`page_words` uints) of what is needed and what its pages hold (the epoch
// they refer to, a bit per page holding that epoch's depth and one per page filled with
// far depth at it; shadow_face_decide.comp), and each drawn record a bit per page drawn.
// A page-list entry: its record | page << kEntryPageShift, kEntryFill set to fill the page
// with far depth (and a white tint) instead of resolving the scratch.
const uint kEntryPageShift = 16;
const uint kEntryFill = 0x80000000u;
const uint kPageShift = ANTUMBRA_PAGE_SHIFT;
const uint kPageSize = 128;  // 1 << kPageShift
const float kPageMargin = 72.0;
// The largest atlas face the compute rasteriser takes: its pages (181^2) fit the 15 bits a
// page-list entry names them in (point_shadow_atlas_desc.cpp, SHD007).
const uint kMaxPagedFace = 23168;

ANTUMBRA_SHARED_END

#endif
