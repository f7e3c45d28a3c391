// Internal (text module): line break opportunities by the Unicode line breaking algorithm
// (UAX #14), from ICU's line break iterator: so CJK and Thai (dictionary-based) text wraps between
// words and characters as their readers expect, and Latin text at spaces and after hyphens.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace casteljau::text_detail {

// Fills `breaks` with para.size() + 1 entries: breaks[k] is 1 when a line may break before
// para[k] (0 < k < size), else 0. `language`: a BCP 47 tag that tailors the rules (ja: Japanese
// line breaking), or "". Without ICU (it cannot be opened), breaks follow spaces only.
void line_break_opportunities(std::u32string_view para, const std::string& language, std::vector<char>& breaks);

}  // namespace casteljau::text_detail
