#pragma once
// A validator for the subset of JSON Schema that the generated scene schema uses (type,
// const, enum, numeric bounds, properties, required, additionalProperties, items,
// minItems, maxItems, oneOf and local $ref), so the tests check the shipped scenes against
// the schema itself without a JSON Schema library (Debian's are Python or Java).

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace antumbra::scene::test {

// The problems of `value` against `schema` (whose "$defs" resolve "#/$defs/NAME"), each
// "POINTER: what"; empty when it validates.
std::vector<std::string> schema_problems(const nlohmann::json& schema, const nlohmann::json& value);

}  // namespace antumbra::scene::test
