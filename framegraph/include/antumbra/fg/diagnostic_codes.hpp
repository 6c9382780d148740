#pragma once
// The catalogue of diagnostic codes. Codes are stable: tests, tools and the editor
// match on them, so a code is never reused for another meaning.
//
//   FG000-FG009  file and JSON syntax           (json_document.cpp)
//   FG010-FG029  document structure and types   (graph description)
//   FG030-FG049  passes, ports and parameters    (resolve/bind)
//   FG050-FG069  resources, formats and sizes    (bind)
//   FG070-FG089  dependency graph               (cycles, writers, outputs)
//   SC000-SC099  scene files                     (engine/scene)
//   SH000-SH099  shaders                         (engine/shader)
//   ED000-ED099  documents the editor opens      (editor/model, editor_codes.hpp)

namespace antumbra::fg::codes {

// File and syntax.
inline constexpr const char* kFileUnreadable = "FG000";
inline constexpr const char* kJsonSyntax = "FG001";
inline constexpr const char* kJsonEmpty = "FG002";
inline constexpr const char* kJsonInvalidUtf8 = "FG003";
inline constexpr const char* kJsonDuplicateKey = "FG004";
inline constexpr const char* kJsonTooDeep = "FG005";

// Document structure and JSON types (graph_desc.cpp).
inline constexpr const char* kWrongType = "FG010";        // a value has the wrong JSON type
inline constexpr const char* kUnknownKey = "FG011";       // unknown key (with "did you mean")
inline constexpr const char* kMissingKey = "FG012";       // a required key is missing
inline constexpr const char* kVersionMissing = "FG013";   // no "version" at the root
inline constexpr const char* kVersionUnsupported = "FG014";  // version < 1 or newer than supported
inline constexpr const char* kInvalidName = "FG015";      // name is not an identifier
inline constexpr const char* kDuplicatePass = "FG016";    // two passes with one name
inline constexpr const char* kNoPasses = "FG017";         // "passes" is empty

// Passes, ports and parameters (resolve/bind).
inline constexpr const char* kUnknownPassType = "FG030";
inline constexpr const char* kUnknownParam = "FG031";
inline constexpr const char* kParamType = "FG032";        // parameter has the wrong JSON type
inline constexpr const char* kParamRange = "FG033";       // parameter outside [min, max]
inline constexpr const char* kParamChoice = "FG034";      // not one of the enumeration's choices
inline constexpr const char* kUnknownPort = "FG035";
inline constexpr const char* kPortDirection = "FG036";    // output port under "in" or vice versa
inline constexpr const char* kPortUnbound = "FG037";      // a required port has no resource
inline constexpr const char* kUnknownAfter = "FG038";     // "after" names no pass
inline constexpr const char* kDoubleWrite = "FG039";      // one pass writes a resource twice
inline constexpr const char* kPortKind = "FG040";         // image port bound to a buffer, ...
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

// Dependency graph.
inline constexpr const char* kReadNeverWritten = "FG070";  // read of a resource nobody wrote
inline constexpr const char* kCycle = "FG071";             // message lists the edges left
inline constexpr const char* kOutputNotImage = "FG072";
inline constexpr const char* kOutputNotProduced = "FG073";  // no executed pass writes it
inline constexpr const char* kPassCulled = "FG074";         // note: outputs reach nothing
inline constexpr const char* kPassDisabled = "FG075";       // note: "enabled": false

// Pass-specific checks over the whole plan (PassDesc::check).
inline constexpr const char* kLayerCapExceedsStorage = "FG090";  // cap k > layers storage holds
inline constexpr const char* kLayerStorageMismatch = "FG091";    // layered images disagree
inline constexpr const char* kDerivedMapMismatch = "FG092";  // map derived from the atlas misfits

// The executor could not realise a valid plan on this device.
inline constexpr const char* kRealiseFailed = "FG100";

}  // namespace antumbra::fg::codes
