// The maps derived per face from the shadow atlas (shadow-min-filter, shadow-moments),
// valid GLSL and C++: the bindings every step of theirs shares (common/scratch_array.hpp's
// face steps) and, over a paged atlas, the record list that derived_list.comp writes for
// the steps' indirect dispatches (docs/technique.md, "Page pool", "Derived maps through
// the tables").
#ifndef ANTUMBRA_DERIVED_MAPS_H
#define ANTUMBRA_DERIVED_MAPS_H

#include "glsl_cpp.h"

ANTUMBRA_SHARED_BEGIN

// Every step: the shadow data, the sampled input, the storage output; over a paged atlas
// also its page tables and the listed records (after the steps' dispatch arguments).
ANTUMBRA_BINDING(kDerivedShadowData, 0)
ANTUMBRA_BINDING(kDerivedInput, 1)
ANTUMBRA_BINDING(kDerivedOutput, 2)
ANTUMBRA_BINDING(kDerivedPageTables, 3)
ANTUMBRA_BINDING(kDerivedRecords, 4)

const uint kDerivedListGroup = 64;  // derived_list.comp: a face record per thread

// derived_list.comp's push constants (in GLSL only there: the steps have their own).
#if defined(__cplusplus) || defined(ANTUMBRA_DERIVED_LIST)
ANTUMBRA_PUSH_CONSTANTS(DerivedListPush) {
  uint records;    // face records the shadow data holds
  uint force_all;  // 1: every owned record (first frame, new images); 0: drawn ones only
};
#endif

ANTUMBRA_SHARED_END

#endif
