// Text stage, line breaking: UAX #14 break opportunities through ICU's line break iterator
// (src/text/line_break.hpp; ICU is opened on first use, src/text/icu_library.hpp). The paragraph
// is converted to UTF-16 for ICU, and each opportunity mapped back to its code point.
#include "text/line_break.hpp"

#include <unicode/ubrk.h>
#include <unicode/utypes.h>

#include <memory>

#include "text/icu_library.hpp"

namespace casteljau::text_detail {

void line_break_opportunities(std::u32string_view para, const std::string& language, std::vector<char>& breaks) {
    const std::size_t n = para.size();
    breaks.assign(n + 1, 0);
    if (n < 2) return;
    std::u16string utf16;
    std::vector<std::size_t> code_point_at;  // UTF-16 index -> code point index
    utf16.reserve(n);
    code_point_at.reserve(n + 1);
    for (std::size_t i = 0; i < n; ++i) {
        char32_t c = para[i];
        if (c > 0x10ffff || (c >= 0xd800 && c < 0xe000)) c = 0xfffd;
        if (c >= 0x10000) {
            utf16.push_back(static_cast<char16_t>(0xd800 + ((c - 0x10000) >> 10)));
            utf16.push_back(static_cast<char16_t>(0xdc00 + ((c - 0x10000) & 0x3ff)));
            code_point_at.push_back(i);
            code_point_at.push_back(i);
        } else {
            utf16.push_back(static_cast<char16_t>(c));
            code_point_at.push_back(i);
        }
    }
    code_point_at.push_back(n);
    const icu_library::Api* icu = icu_library::api();
    UErrorCode status = U_ZERO_ERROR;
    auto close = [icu](UBreakIterator* b) { icu->break_close(b); };
    std::unique_ptr<UBreakIterator, decltype(close)> it(
        icu ? icu->break_open(UBRK_LINE, language.c_str(), reinterpret_cast<const UChar*>(utf16.data()),
                              static_cast<int32_t>(utf16.size()), &status)
            : nullptr,
        close);
    if (!icu || U_FAILURE(status) || !it) {
        for (std::size_t k = 1; k < n; ++k) breaks[k] = para[k - 1] == U' ' && para[k] != U' ';
        return;
    }
    for (int32_t b = icu->break_first(it.get()); b != UBRK_DONE; b = icu->break_next(it.get())) {
        const std::size_t k = code_point_at[static_cast<std::size_t>(b)];
        if (k > 0 && k < n) breaks[k] = 1;
    }
}

}  // namespace casteljau::text_detail
