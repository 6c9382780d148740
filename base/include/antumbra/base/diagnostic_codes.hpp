#pragma once
// The catalogue of diagnostic codes: every code the program reports, in one table, so a
// code is never reused for another meaning. Codes are stable: tests, tools and the editor
// match on them.
//
//   FG000-FG009  file and JSON syntax           (base/src/json_parser.cpp; graphs and scenes)
//   FG010-FG029  document structure and types   (graph description)
//   FG030-FG049  passes, ports and parameters    (resolve/bind)
//   FG050-FG069  resources, formats and sizes    (bind)
//   FG070-FG089  dependency graph               (cycles, writers, outputs)
//   FG090-FG109  checks over the whole plan, realising it on a device
//   SC000-SC099  scene files                     (engine/scene)
//   SH000-SH099  shaders                         (engine/core shader compiler, pass reflection)
//   ED000-ED199  documents the editor opens, edit scripts (editor/model)
//   SHD, LY, TL, SM, SD  pass-specific checks and frame reports (passes/)
//   QU000-QU099  the quality comparison          (app/cmd_compare.cpp)

namespace antumbra::codes {

// The graph core's codes.
namespace graph {
// File and syntax.
inline constexpr const char* kFileUnreadable = "FG000";
inline constexpr const char* kJsonSyntax = "FG001";
inline constexpr const char* kJsonEmpty = "FG002";
inline constexpr const char* kJsonInvalidUtf8 = "FG003";
inline constexpr const char* kJsonDuplicateKey = "FG004";
inline constexpr const char* kJsonTooDeep = "FG005";
inline constexpr const char* kJsonTooLarge = "FG006";  // past JsonParseOptions::max_bytes

// Document structure and JSON types (graph_desc.cpp).
inline constexpr const char* kWrongType = "FG010";           // a value has the wrong JSON type
inline constexpr const char* kUnknownKey = "FG011";          // unknown key (with "did you mean")
inline constexpr const char* kMissingKey = "FG012";          // a required key is missing
inline constexpr const char* kVersionMissing = "FG013";      // no "version" at the root
inline constexpr const char* kVersionUnsupported = "FG014";  // version < 1 or newer than supported
inline constexpr const char* kInvalidName = "FG015";         // name is not an identifier
inline constexpr const char* kDuplicatePass = "FG016";       // two passes with one name
inline constexpr const char* kNoPasses = "FG017";            // "passes" is empty

// Passes, ports and parameters (resolve/bind).
inline constexpr const char* kUnknownPassType = "FG030";
inline constexpr const char* kUnknownParam = "FG031";
inline constexpr const char* kParamType = "FG032";    // parameter has the wrong JSON type
inline constexpr const char* kParamRange = "FG033";   // parameter outside [min, max]
inline constexpr const char* kParamChoice = "FG034";  // not one of the enumeration's choices
inline constexpr const char* kUnknownPort = "FG035";
inline constexpr const char* kPortDirection = "FG036";      // output port under "in" or vice versa
inline constexpr const char* kPortUnbound = "FG037";        // a required port has no resource
inline constexpr const char* kUnknownAfter = "FG038";       // "after" names no pass
inline constexpr const char* kDoubleWrite = "FG039";        // one pass writes a resource twice
inline constexpr const char* kPortKind = "FG040";           // image port bound to a buffer, ...
inline constexpr const char* kReadWriteSamePass = "FG041";  // read and written by one pass

// Resources, formats and sizes.
inline constexpr const char* kUnknownFormat = "FG050";
inline constexpr const char* kBadSize = "FG051";
inline constexpr const char* kBadLayers = "FG052";
inline constexpr const char* kUnknownResource = "FG053";  // with "did you mean"
inline constexpr const char* kFormatRejected = "FG054";   // format the port does not accept
inline constexpr const char* kLayersRejected = "FG055";   // layer count outside the port's range
inline constexpr const char* kSizeMismatch = "FG056";     // attachments of one size group differ
inline constexpr const char* kUnknownKind = "FG057";      // kind is not image/buffer
inline constexpr const char* kUnusedResource = "FG058";   // warning: declared, never used
inline constexpr const char* kBadImport = "FG059";  // "import" on a buffer, or with "persistent"

// Dependency graph.
inline constexpr const char* kReadNeverWritten = "FG070";  // read of a resource nobody wrote
inline constexpr const char* kCycle = "FG071";             // at the closing edge; lists the cycle
inline constexpr const char* kOutputNotImage = "FG072";
inline constexpr const char* kOutputNotProduced = "FG073";  // no executed pass writes it
inline constexpr const char* kPassCulled = "FG074";         // note: outputs reach nothing
inline constexpr const char* kPassDisabled = "FG075";       // note: "enabled": false
inline constexpr const char* kParamChosen = "FG076";        // note: an "auto" value chosen

// Pass-specific checks over the whole plan (PassDesc::check).
inline constexpr const char* kLayerCapExceedsStorage = "FG090";  // cap k > layers storage holds
// FG091 (layered images of different layer counts) is now the port contract FG092.
// A port's declared size or layer contract (fg::PortDesc::size_of, layers_of) is broken:
// "same size as `shadow`", "an exact integer fraction of `atlas`".
inline constexpr const char* kPortContract = "FG092";
// A pass keeps work in an output from frame to frame (cached shadow faces, their filtered
// maps): the resource must be persistent (or imported: the host's to keep).
inline constexpr const char* kNotKeptBetweenFrames = "FG093";

// The executor could not realise a valid plan on this device.
inline constexpr const char* kRealiseFailed = "FG100";
// A host's image bound to an imported resource (docs/integration.md): the wrong format,
// extent, layers or usage, a null handle, or a name the graph does not import.
inline constexpr const char* kImportMismatch = "FG101";
}  // namespace graph

// Scene files (SC000-SC099). File reading and JSON syntax keep FG000-FG005, because the
// same JSON layer reports them for graphs and scenes alike.
namespace scene {
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
inline constexpr const char* kObjectKind = "SC013";     // not one of primitive/gltf/scene
inline constexpr const char* kBadArchShape = "SC014";   // opening does not fit the arch
inline constexpr const char* kTooManyCopies = "SC015";  // "repeat" expands past the limit
// Scene instancing (an object's "scene" key), reported at that key.
inline constexpr const char* kInstanceFileMissing = "SC016";
inline constexpr const char* kInstanceCycle = "SC017";       // a file instances itself
inline constexpr const char* kInstanceInvalid = "SC018";     // its own errors follow, in its file
inline constexpr const char* kInstanceSunSkipped = "SC019";  // warning: one sun per scene

// Lights and camera (SC020-SC029).
inline constexpr const char* kLightNameEmpty = "SC020";
inline constexpr const char* kLightNameDuplicate = "SC021";
inline constexpr const char* kLightTypeUnsupported = "SC022";  // not point/spot/directional
inline constexpr const char* kCameraDegenerate = "SC023";      // target == position, up || view
inline constexpr const char* kSecondDirectional = "SC024";     // more than one directional light
inline constexpr const char* kLightDirectionZero = "SC025";    // spot/directional direction ~ 0
inline constexpr const char* kSpotAngles = "SC026";            // inner > outer
inline constexpr const char* kLightKeyIgnored = "SC027";       // warning: key unused by this type
inline constexpr const char* kTooManyLights = "SC028";  // past kMaxSceneLights (scene_file.hpp)

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
inline constexpr const char* kGltfImage =
    "SC043";  // warning: image missing, corrupt or too large (the factor is used)
inline constexpr const char* kGltfMaterial =
    "SC044";  // warning: material value invalid or unsupported (its default is used)
inline constexpr const char* kGltfLight =
    "SC045";  // warning: KHR_lights_punctual light or reference invalid (skipped)
inline constexpr const char* kGltfPathOutside =
    "SC046";  // a glTF URI or scene path outside its file's folder (warning when allowed)

// Dynamic objects (SC050-SC059), reported at the "dynamic" entry.
inline constexpr const char* kUnknownObject = "SC050";    // names no object of the file
inline constexpr const char* kDynamicTwice = "SC051";     // warning: listed more than once
inline constexpr const char* kDynamicNoMeshes = "SC052";  // warning: the object has no mesh
}  // namespace scene

// Shaders (SH000-SH099).
namespace shader {
inline constexpr const char* kUnreadable = "SH000";      // source file missing/unreadable
inline constexpr const char* kCompile = "SH001";         // glslang compile error (file:line)
inline constexpr const char* kUnknownStage = "SH002";    // no stage given, unknown extension
inline constexpr const char* kLink = "SH003";            // glslang link / SPIR-V generation
inline constexpr const char* kCompileWarning = "SH004";  // glslang warning
// A shader's reflected descriptor bindings, push-constant size or vertex inputs disagree
// with the pass's C++ declaration (passes/common/pass_support.hpp).
inline constexpr const char* kInterfaceMismatch = "SH010";
}  // namespace shader

// Documents the editor's model opens and edit scripts (docs/edit-script.md). The engine's
// own codes (FG..., SC...) come through unchanged where its parsers are used.
namespace editor {
inline constexpr const char* kNotAnObject = "ED001";     // the document root is not an object
inline constexpr const char* kNewerVersion = "ED002";    // written by a newer format version
inline constexpr const char* kLightsNotArray = "ED010";  // "lights" is not an array
inline constexpr const char* kLightNotObject = "ED011";  // a light is not an object
inline constexpr const char* kLightField = "ED012";      // a light field has the wrong type/range
inline constexpr const char* kLightName = "ED013";       // missing, empty or duplicate name
inline constexpr const char* kSecondSun = "ED014";       // more than one directional light
inline constexpr const char* kNoRecovery = "ED020";      // recover() without a recovery file
// A connection the graph editor refuses although the compiler would take it: a second pass
// writing a resource (the compiler orders the writes and culls the earlier writer).
inline constexpr const char* kSecondWriter = "ED030";
// Edit scripts (docs/edit-script.md): a step that ran and failed; a script that is malformed
// (unknown action or key, missing key, wrong value type), found before anything runs.
inline constexpr const char* kStepFailed = "ED100";
inline constexpr const char* kScriptMalformed = "ED101";
}  // namespace editor

// point-shadow-atlas.
namespace shadow_atlas {
inline constexpr const char* kShadowDataTooSmall =
    "SHD001";  // shadowData smaller than the atlas needs
inline constexpr const char* kLightsUnshadowed = "SHD002";  // warning: lights do not fit the atlas
// SHD003 (a colour map with fewer layers) is now the port contract FG092.
inline constexpr const char* kRasterizerFormat = "SHD004";  // atlas format vs the rasteriser
inline constexpr const char* kFacesDegraded = "SHD005";  // note: faces drawn smaller (atlas full)
inline constexpr const char* kTooManyLayers = "SHD006";  // atlas layers past what a face names
// compute rasteriser: atlas faces with more pages than a page list names
inline constexpr const char* kFaceTooLarge = "SHD007";
inline constexpr const char* kFaceStats = "SHD010";  // note: faces culled/drawn/cached
}  // namespace shadow_atlas

// gbuffer.
namespace gbuffer {
inline constexpr const char* kRasterizerFormat = "GB001";  // depth format vs the rasteriser
}  // namespace gbuffer

// light-layering.
namespace layering {
inline constexpr const char* kOverCap = "LY001";             // warning: layout needs more layers
inline constexpr const char* kLayerTableTooSmall = "LY010";  // layerTable buffer too small
}  // namespace layering

// tiled-lighting (and its hard / pcf / pcss variants).
namespace lighting {
inline constexpr const char* kAtlasWithoutData = "TL001";  // atlas and shadowData not both bound
inline constexpr const char* kModeNeedsAtlas = "TL002";    // shadows mode needs the atlas
inline constexpr const char* kShadowDataTooSmall =
    "TL003";                                            // shadowData smaller than the atlas needs
inline constexpr const char* kLayeredInputs = "TL004";  // layered mode needs layerTable, shadow
inline constexpr const char* kLayerTableTooSmall = "TL005";  // layerTable buffer too small
inline constexpr const char* kMomentsInputs = "TL006";       // moment modes need moments + atlas
inline constexpr const char* kMomentsTechnique = "TL007";   // mode differs from the map's technique
inline constexpr const char* kSdfInputs = "TL008";          // sdf mode needs sdf + sdfInfo
inline constexpr const char* kPenumbraMapInputs = "TL009";  // penumbra-map mode's inputs
}  // namespace lighting

// shadow-moments.
namespace moments {
inline constexpr const char* kFormat = "SM001";  // map format cannot hold the technique
}  // namespace moments

// scene-sdf.
namespace sdf {
inline constexpr const char* kTooSmall = "SD001";       // a side of the volume below 8 voxels
inline constexpr const char* kOverBudget = "SD002";     // the volume exceeds memoryBudget
inline constexpr const char* kNotPersistent = "SD003";  // baked once: must be persistent
inline constexpr const char* kBaked = "SD004";          // note: a bake, its size and memory
inline constexpr const char* kInfoTooSmall = "SD005";   // sdfInfo buffer below SdfInfo's size
}  // namespace sdf

// penumbra-wedges.
namespace wedges {
inline constexpr const char* kSummary = "PW001";       // note: edges, depth layers, memory
inline constexpr const char* kEdgesDropped = "PW002";  // warning: silhouettes over edgesPerFace
inline constexpr const char* kPeeled = "PW003";        // `peeled` bound iff peelingDepth is 3
// PW004 (`peeled` of another size than the map) is now the port contract FG092.
inline constexpr const char* kSilhouettesTooLarge = "PW005";  // silhouette buffer over 1 GiB
}  // namespace wedges

// shadow-reference (SHR001, a directional light drawn unshadowed, is retired: never reused).
namespace reference {
inline constexpr const char* kProgress = "SHR002";  // note: samples taken of the reference so far
}  // namespace reference

// antumbra quality.
namespace quality {
inline constexpr const char* kRankingUnreliable = "QU001";  // warning: too few pixels to rank
}  // namespace quality

}  // namespace antumbra::codes
