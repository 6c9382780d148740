// The penumbra-wedges pass's shader interface (silhouettes.comp, wedge_args.comp,
// peel.vert/.frag, wedge.vert/.frag), valid GLSL and C++: its structs, push-constant block
// and binding numbers, written once for the shaders, the set layout and the descriptor
// writes (docs/architecture.md, "One source for CPU and GPU").
#ifndef ANTUMBRA_PENUMBRA_WEDGES_INTERFACE_H
#define ANTUMBRA_PENUMBRA_WEDGES_INTERFACE_H

#include "../interface/shared/glsl_cpp.h"

// WedgeEdge.vertices.w of an edge with one triangle.
#define ANTUMBRA_NO_TRIANGLE 0xffffffffu
// WedgeEdge.welded.z: the second triangle runs along the edge in the first one's
// direction (the mesh's winding flips there). Informational: silhouettes.comp orients the
// second triangle by the first whatever its winding, so a flat surface stays flat.
#define ANTUMBRA_EDGE_FLIPPED 1u
// Vertices per silhouette edge: an outer and an inner quad, two triangles each.
#define ANTUMBRA_WEDGE_VERTICES 12u

ANTUMBRA_SHARED_BEGIN

// One edge of the merged geometry: x, y its vertices (indices into the scene's vertex
// buffer) in the first triangle's winding, z that triangle's third vertex, w the second
// triangle's (ANTUMBRA_NO_TRIANGLE: none); welded.xy the welded vertices of x and y
// (their normals), welded.z flags.
struct WedgeEdge {
  uvec4 vertices;
  uvec4 welded;
};

// One silhouette edge from one light: its end points (w unused) and the unit directions
// their wedge corners move along, perpendicular to the light's ray and scaled so that
// the wedge is `outer` wide across the edge (w unused).
struct Silhouette {
  vec4 b;
  vec4 c;
  vec4 db;
  vec4 dc;
};

ANTUMBRA_BINDING(kWedgeShadowData, 0)
ANTUMBRA_BINDING(kWedgeVertices, 1)
ANTUMBRA_BINDING(kWedgeEdges, 2)
ANTUMBRA_BINDING(kWedgeNormals, 3)
ANTUMBRA_BINDING(kWedgeSilhouettes, 4)
ANTUMBRA_BINDING(kWedgeCounts, 5)
ANTUMBRA_BINDING(kWedgeArgs, 6)
// Peeling: the layer in front (the atlas, then the second layer); wedges: the atlas (Z1)
// and the second layer (Z2).
ANTUMBRA_BINDING(kWedgeFirst, 7)
ANTUMBRA_BINDING(kWedgeSecond, 8)
// Materials (silhouettes.comp: one-sided and alpha-tested triangles) and base-colour
// textures (peel.frag with CUT: the peeling of cut casters).
ANTUMBRA_BINDING(kWedgeMaterials, 9)
ANTUMBRA_BINDING(kWedgeSrgbTextures, 10)
ANTUMBRA_BINDING(kWedgeSampler, 11)
// Over a page pool (point-shadow-atlas pagePool): its page tables, through which the
// atlas (Z1) is read; shaders compiled with PAGED.
ANTUMBRA_BINDING(kWedgePageTables, 12)

ANTUMBRA_PUSH_CONSTANTS(PenumbraWedgesPush) {
  uint edge_count;
  uint capacity;  // silhouette edges per face (a point light's segment holds 6x)
  uint layers;    // atlas layers
  uint layer;     // the face a draw renders
  float outer;    // outer wedge width, times the light's radius
  float inner;    // inner wedge width, times the light's radius
  float beta;     // metres: inner fragments this far behind Z1 are dropped
  float gap;      // metres: peeling skips surfaces this close behind the layer in front
  uint peeling_depth;
  uint first_paged;  // 1: kWedgeFirst is the atlas and a page pool (read through the tables)
  vec2 extent;       // the rendering's size in texels
};

ANTUMBRA_SHARED_END

#endif
