#pragma once
// How messages name things: 'name' in single quotes, and lists of names cut short so that
// a layout of thousands of lights reports a line, not a page.

#include <cstddef>
#include <span>
#include <string>
#include <string_view>

namespace antumbra::base {

// Names listed in a message before "... and N more".
inline constexpr std::size_t kNamesInMessage = 8;

// 'name'.
std::string quote_name(std::string_view name);

// "'a', 'b', 'c'" or, past `shown` names, "'a', 'b', ... and 998 more".
std::string name_list(std::span<const std::string> names, std::size_t shown = kNamesInMessage);

}  // namespace antumbra::base
