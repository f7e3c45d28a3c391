// Text stage, layout: bidi levels and visual reordering (include/casteljau/shaping.hpp), a compact
// subset of the Unicode bidirectional algorithm (UAX #9).
//
// Character classes come from HarfBuzz's Unicode functions: letters (and spacing marks) of a
// right-to-left script are strong R, other letters strong L, decimal digits are numbers,
// non-spacing marks take the class of the character before them, everything else is neutral;
// LRM is L, RLM and ALM are R. Resolution (rules W1, W7, N1, N2, I1, I2 for a single paragraph
// without explicit embeddings) yields levels 0 (LTR), 1 (RTL) and 2 (LTR numbers or Latin inside
// RTL). L2 reordering turns levels into a left-to-right visual order.
#include "casteljau/shaping.hpp"

#include <hb.h>

#include <algorithm>

namespace casteljau {

namespace {

enum class BidiClass : std::uint8_t { L, R, Number, Mark, Neutral };

BidiClass bidi_class(char32_t c) {
    if (c == 0x200e) return BidiClass::L;                 // LEFT-TO-RIGHT MARK
    if (c == 0x200f || c == 0x061c) return BidiClass::R;  // RIGHT-TO-LEFT MARK, ARABIC LETTER MARK
    hb_unicode_funcs_t* uf = hb_unicode_funcs_get_default();
    switch (hb_unicode_general_category(uf, c)) {
        case HB_UNICODE_GENERAL_CATEGORY_UPPERCASE_LETTER:
        case HB_UNICODE_GENERAL_CATEGORY_LOWERCASE_LETTER:
        case HB_UNICODE_GENERAL_CATEGORY_TITLECASE_LETTER:
        case HB_UNICODE_GENERAL_CATEGORY_MODIFIER_LETTER:
        case HB_UNICODE_GENERAL_CATEGORY_OTHER_LETTER:
        case HB_UNICODE_GENERAL_CATEGORY_SPACING_MARK:
        case HB_UNICODE_GENERAL_CATEGORY_LETTER_NUMBER:
        case HB_UNICODE_GENERAL_CATEGORY_PRIVATE_USE:
            return hb_script_get_horizontal_direction(hb_unicode_script(uf, c)) == HB_DIRECTION_RTL ? BidiClass::R
                                                                                                    : BidiClass::L;
        case HB_UNICODE_GENERAL_CATEGORY_DECIMAL_NUMBER: return BidiClass::Number;
        case HB_UNICODE_GENERAL_CATEGORY_NON_SPACING_MARK:
        case HB_UNICODE_GENERAL_CATEGORY_ENCLOSING_MARK: return BidiClass::Mark;
        default: return BidiClass::Neutral;
    }
}

}  // namespace

int resolve_bidi_levels(std::u32string_view para, TextDirection direction, std::vector<std::uint8_t>& levels) {
    const std::size_t n = para.size();
    std::vector<BidiClass> t(n);
    for (std::size_t i = 0; i < n; ++i) t[i] = bidi_class(para[i]);

    int p = 0;  // paragraph level
    if (direction == TextDirection::RightToLeft) {
        p = 1;
    } else if (direction == TextDirection::Auto) {
        for (BidiClass c : t) {  // P2, P3: the first strong character
            if (c == BidiClass::L) break;
            if (c == BidiClass::R) {
                p = 1;
                break;
            }
        }
    }
    const BidiClass sos = p ? BidiClass::R : BidiClass::L;

    // W1: a mark takes the class of the character before it (the paragraph direction at the start).
    for (std::size_t i = 0; i < n; ++i)
        if (t[i] == BidiClass::Mark) t[i] = i ? t[i - 1] : sos;
    // W7: a number after L (or at the start of an LTR paragraph) becomes L.
    BidiClass last_strong = sos;
    for (std::size_t i = 0; i < n; ++i) {
        if (t[i] == BidiClass::L || t[i] == BidiClass::R)
            last_strong = t[i];
        else if (t[i] == BidiClass::Number && last_strong == BidiClass::L)
            t[i] = BidiClass::L;
    }
    // N1, N2: neutrals between two like directions take it (numbers count as R), others the
    // paragraph's direction.
    auto dir_of = [](BidiClass c) { return c == BidiClass::L ? BidiClass::L : BidiClass::R; };
    for (std::size_t i = 0; i < n;) {
        if (t[i] != BidiClass::Neutral) {
            ++i;
            continue;
        }
        std::size_t j = i;
        while (j < n && t[j] == BidiClass::Neutral) ++j;
        const BidiClass before = i ? dir_of(t[i - 1]) : sos;
        const BidiClass after = j < n ? dir_of(t[j]) : sos;
        const BidiClass d = before == after ? before : sos;
        for (std::size_t k = i; k < j; ++k) t[k] = d;
        i = j;
    }
    // I1, I2.
    levels.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        switch (t[i]) {
            case BidiClass::L: levels[i] = static_cast<std::uint8_t>(p ? 2 : 0); break;
            case BidiClass::R: levels[i] = 1; break;
            default: levels[i] = 2; break;  // numbers
        }
    }
    return p;
}

void bidi_visual_order(std::span<const std::uint8_t> levels, std::vector<std::size_t>& order) {
    const std::size_t n = levels.size();
    order.resize(n);
    for (std::size_t i = 0; i < n; ++i) order[i] = i;
    if (n == 0) return;
    const std::uint8_t hi = *std::max_element(levels.begin(), levels.end());
    std::uint8_t lo_odd = 255;
    for (std::uint8_t l : levels)
        if (l & 1) lo_odd = std::min(lo_odd, l);
    if (lo_odd == 255) {
        if (hi == 0) return;
        lo_odd = 1;  // only even levels above 0 (cannot happen with resolve_bidi_levels, harmless)
    }
    for (int lev = hi; lev >= lo_odd; --lev) {
        for (std::size_t i = 0; i < n;) {
            if (levels[order[i]] < lev) {
                ++i;
                continue;
            }
            std::size_t j = i;
            while (j < n && levels[order[j]] >= lev) ++j;
            std::reverse(order.begin() + static_cast<std::ptrdiff_t>(i),
                         order.begin() + static_cast<std::ptrdiff_t>(j));
            i = j;
        }
    }
}

}  // namespace casteljau
