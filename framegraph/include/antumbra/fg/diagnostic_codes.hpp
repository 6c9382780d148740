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

namespace antumbra::fg::codes {

// File and syntax.
inline constexpr const char* kFileUnreadable = "FG000";
inline constexpr const char* kJsonSyntax = "FG001";
inline constexpr const char* kJsonEmpty = "FG002";
inline constexpr const char* kJsonInvalidUtf8 = "FG003";
inline constexpr const char* kJsonDuplicateKey = "FG004";
inline constexpr const char* kJsonTooDeep = "FG005";

}  // namespace antumbra::fg::codes
