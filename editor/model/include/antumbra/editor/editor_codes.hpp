#pragma once
// Diagnostic codes of the editor's model (documents it cannot open as they are). The
// engine's own codes (FG..., SC...) come through unchanged where its parsers are used.

namespace antumbra::editor::codes {

inline constexpr const char* kNotAnObject = "ED001";     // the document root is not an object
inline constexpr const char* kNewerVersion = "ED002";    // written by a newer format version
inline constexpr const char* kLightsNotArray = "ED010";  // "lights" is not an array
inline constexpr const char* kLightNotObject = "ED011";  // a light is not an object
inline constexpr const char* kLightField = "ED012";      // a light field has the wrong type/range
inline constexpr const char* kLightName = "ED013";       // missing, empty or duplicate name
inline constexpr const char* kSecondSun = "ED014";       // more than one directional light
inline constexpr const char* kNoRecovery = "ED020";      // recover() without a recovery file
// Edit scripts (docs/edit-script.md): a step that ran and failed; a script that is malformed
// (unknown action or key, missing key, wrong value type), found before anything runs.
inline constexpr const char* kStepFailed = "ED100";
inline constexpr const char* kScriptMalformed = "ED101";

}  // namespace antumbra::editor::codes
