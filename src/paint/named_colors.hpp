// Paint stage: the 148 CSS named colours (CSS Color Module Level 4, section 6.1), private to the library.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

#include "casteljau/paint.hpp"

namespace casteljau::detail {

struct NamedColor {
    std::string_view name;  // lower case
    std::uint32_t rgb;      // 0xRRGGBB, opaque
};

// The table, sorted by name (checked at compile time); exposed for tests.
std::span<const NamedColor> named_colors();

// Looks up a name (any ASCII case) by binary search; nullopt when it is not a CSS colour name.
// `transparent`, `none` and `currentColor` are not in the table: parse_color handles them.
std::optional<Color> find_named_color(std::string_view name);

}  // namespace casteljau::detail
