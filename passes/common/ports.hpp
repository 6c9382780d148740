#pragma once
// The port names of the built-in passes. Each pass's description (*_desc.cpp) and its
// runtime (*_pass.cpp) name a port through the same constant, and fgvk::PassBindings takes
// only an fg::PortId, so the two cannot drift apart (docs/adding-a-pass.md). Passes share
// a name where the port means the same thing (the G-buffer's `depth` is what every
// screen-space pass reads as `depth`), which is what lets a graph swap one pass for another.

#include "antumbra/fg/reflection.hpp"

namespace antumbra::passes::port {

// G-buffer and screen images.
inline constexpr fg::PortId kDepth{"depth"};
inline constexpr fg::PortId kNormal{"normal"};
inline constexpr fg::PortId kAlbedo{"albedo"};
inline constexpr fg::PortId kEmissive{"emissive"};
inline constexpr fg::PortId kHdr{"hdr"};
inline constexpr fg::PortId kLdr{"ldr"};
inline constexpr fg::PortId kView{"view"};

// Shadow maps and the buffers that describe them.
inline constexpr fg::PortId kAtlas{"atlas"};
inline constexpr fg::PortId kColour{"colour"};
inline constexpr fg::PortId kMinDepth{"minDepth"};
inline constexpr fg::PortId kMoments{"moments"};
inline constexpr fg::PortId kShadowData{"shadowData"};
inline constexpr fg::PortId kPageTables{"pageTables"};
inline constexpr fg::PortId kLayerTable{"layerTable"};
inline constexpr fg::PortId kSdf{"sdf"};
inline constexpr fg::PortId kSdfInfo{"sdfInfo"};
inline constexpr fg::PortId kPenumbraMap{"penumbraMap"};
inline constexpr fg::PortId kPeeled{"peeled"};

// Screen-space shadow layers and their inputs.
inline constexpr fg::PortId kPenumbra{"penumbra"};
inline constexpr fg::PortId kPenumbraCount{"penumbraCount"};
inline constexpr fg::PortId kHardShadow{"hardShadow"};
inline constexpr fg::PortId kEsm{"esm"};
inline constexpr fg::PortId kTranslucency{"translucency"};
inline constexpr fg::PortId kSource{"source"};
inline constexpr fg::PortId kShadow{"shadow"};

}  // namespace antumbra::passes::port
