#pragma once
// Diagnostic codes of scene files (SC000-SC099, see fg/diagnostic_codes.hpp). Codes are
// stable: tests, tools and the editor match on them; a code is never reused.
// File reading and JSON syntax keep the framegraph's FG000-FG005 codes, because the
// same JSON layer reports them for graphs and scenes alike.

namespace antumbra::scene::codes {

// Document structure (SC001-SC009).
inline constexpr const char* kVersionMissing = "SC001";      // no "version" key
inline constexpr const char* kVersionUnsupported = "SC002";  // newer than supported, or < 1
inline constexpr const char* kWrongType = "SC003";           // e.g. string where a number goes
inline constexpr const char* kUnknownKey = "SC004";          // with "did you mean"
inline constexpr const char* kMissingKey = "SC005";          // a required key is absent
inline constexpr const char* kOutOfRange = "SC006";          // negative range, fovY >= 180...
inline constexpr const char* kBadArity = "SC007";            // vec3 with 2 numbers, etc.

// Objects and materials (SC010-SC019).
inline constexpr const char* kUnknownMaterial = "SC010";
inline constexpr const char* kTransmittanceIgnored = "SC011";  // warning: not translucent
inline constexpr const char* kUnknownPrimitive = "SC012";
inline constexpr const char* kObjectKind = "SC013";     // neither or both of primitive/gltf
inline constexpr const char* kBadArchShape = "SC014";   // opening does not fit the arch
inline constexpr const char* kTooManyCopies = "SC015";  // "repeat" expands past the limit

// Lights and camera (SC020-SC029).
inline constexpr const char* kLightNameEmpty = "SC020";
inline constexpr const char* kLightNameDuplicate = "SC021";
inline constexpr const char* kLightTypeUnsupported = "SC022";  // not point/spot/directional
inline constexpr const char* kCameraDegenerate = "SC023";      // target == position, up || view
inline constexpr const char* kSecondDirectional = "SC024";     // more than one directional light
inline constexpr const char* kLightDirectionZero = "SC025";    // spot/directional direction ~ 0
inline constexpr const char* kSpotAngles = "SC026";            // inner > outer
inline constexpr const char* kLightKeyIgnored = "SC027";       // warning: key unused by this type

// glTF import (SC030-SC049). Reported at the scene object's "gltf" key; the message names
// the glTF file and the JSON Pointer inside it.
inline constexpr const char* kGltfFileMissing = "SC030";
inline constexpr const char* kGltfParse =
    "SC031";  // tinygltf rejected it, or a used property is mistyped
inline constexpr const char* kGltfBadReference = "SC032";     // index of node/mesh/... out of range
inline constexpr const char* kGltfOutOfBounds = "SC033";      // accessor/view past its buffer
inline constexpr const char* kGltfBadAccessor = "SC034";      // type/component type/stride
inline constexpr const char* kGltfIndexOutOfRange = "SC035";  // index value >= vertex count
inline constexpr const char* kGltfNodeCycle = "SC036";
inline constexpr const char* kGltfNonFinite = "SC037";      // NaN/inf positions or matrices
inline constexpr const char* kGltfCountMismatch = "SC038";  // attribute counts, index count % 3
inline constexpr const char* kGltfNoGeometry = "SC039";     // default scene draws no triangle
inline constexpr const char* kGltfUnsupported =
    "SC040";  // sparse, Draco... (warning: points/lines skipped)
inline constexpr const char* kGltfWarning =
    "SC041";  // warning: tinygltf, or unused property mistyped
inline constexpr const char* kGltfTooLarge = "SC042";  // past the import limits

}  // namespace antumbra::scene::codes
