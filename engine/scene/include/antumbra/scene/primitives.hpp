#pragma once
// Procedural primitives in local space. Every primitive is centred on the origin (the
// centre of its bounding box) and has outward normals and counter-clockwise front faces
// (cross(p1 - p0, p2 - p0) points outward; see scene.hpp). All but the plane are closed
// solids, so they cast shadows from every side. UVs are in metres along the face
// (a 2 m wall gets u in [0, 2]) so textures tile at a constant world scale; the sphere
// and the cylinder side use (angle / 2pi, height fraction) instead.
//
// The builders assume valid parameters (positive sizes, segments >= 3); the scene parser
// validates user input before calling them.

#include "antumbra/scene/scene.hpp"

namespace antumbra::scene {

// Axis-aligned box with edge lengths `size`: 24 vertices, 12 triangles, flat normals.
Mesh make_box(const glm::vec3& size);

// Single-sided rectangle in the XZ plane facing +Y, `size` = (x, z) extents.
Mesh make_plane(const glm::vec2& size);

// Cylinder along Y, `segments` around, with flat caps (smooth side normals).
Mesh make_cylinder(float radius, float height, int segments);

// UV sphere: `segments` around Y, `rings` from pole to pole (>= 2).
Mesh make_sphere(float radius, int segments, int rings);

enum class ArchStyle { round, pointed };

// A solid arch extruded along Z: two piers and a curved top around an opening that
// reaches the bottom. Outer size width x height x depth; the opening is
// width - 2 * pier_width wide and its apex lies `crown` below the top. A round arch has
// a semicircular intrados; a pointed (equilateral gothic) one two arcs of radius equal
// to the opening width. Adjacent arches placed `width` apart share flush pier faces.
struct ArchParams {
  float width = 3.0f;
  float height = 4.0f;
  float depth = 0.5f;
  float pier_width = 0.4f;
  float crown = 0.3f;
  ArchStyle style = ArchStyle::round;
  int segments = 12;  // per half of the curve
};

// Height of the opening's springline above the arch's base (where the curve starts);
// negative when the parameters do not fit (opening too wide for the height).
float arch_springline(const ArchParams& params);
Mesh make_arch(const ArchParams& params);

// Signed volume enclosed by a mesh's triangles (local space); positive for a closed mesh
// with outward-facing counter-clockwise triangles. Used by tests and validation.
double signed_volume(const Mesh& mesh);

}  // namespace antumbra::scene
