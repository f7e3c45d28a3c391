// Internal (text module): a compact subset of the Unicode bidirectional algorithm (UAX #9).
//
// Character classes come from HarfBuzz's Unicode functions: letters (and spacing marks) of a
// right-to-left script are strong R, other letters strong L, decimal digits are numbers,
// non-spacing marks take the class of the character before them, everything else is neutral;
// LRM is L, RLM and ALM are R. Resolution (rules W1, W7, N1, N2, I1, I2 for a single paragraph
// without explicit embeddings) yields levels 0 (LTR), 1 (RTL) and 2 (LTR numbers or Latin inside
// RTL). L2 reordering turns levels into a left-to-right visual order.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "casteljau/text.hpp"

namespace casteljau::text_detail {

enum class BidiClass : std::uint8_t { L, R, Number, Mark, Neutral };

BidiClass bidi_class(char32_t c);

// Fills `levels` (one per code point of `para`) and returns the paragraph level (0 or 1).
int resolve_bidi_levels(std::u32string_view para, TextDirection direction, std::vector<std::uint8_t>& levels);

// Visual order (left to right) of items with the given levels, by rule L2: from the highest level
// down to the lowest odd level, reverse every maximal run of items at that level or above.
void visual_order(std::span<const std::uint8_t> levels, std::vector<std::size_t>& order);

}  // namespace casteljau::text_detail
