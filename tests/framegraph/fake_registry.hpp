#pragma once
// A registry of fake pass types modelled on the built-in ones (gbuffer,
// deferred-lighting, tonemap) plus a few shapes the tests, benchmark and fuzzer need.
// Shared by tests/framegraph, bench/ and fuzz/.

#include "antumbra/fg/registry.hpp"

namespace antumbra::fg::testing {

// gbuffer, deferred-lighting, tonemap, blur, composite, shadow-atlas, light-list,
// split, readback (side effects).
Registry make_fake_registry();

}  // namespace antumbra::fg::testing
