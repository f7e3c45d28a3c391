// Text stage, first step: UTF-8 decoding with U+FFFD for invalid input (include/casteljau/text.hpp).
#include <string>
#include <string_view>

#include "casteljau/text.hpp"

namespace casteljau {

namespace {

// What a lead byte of a multi-byte sequence asks of the bytes after it: how many continuation
// bytes, the range of the first of them (narrower than 0x80..0xbf where the second byte rules out
// overlong forms, surrogates and values above U+10FFFF), and the code point's bits it carries.
struct Lead {
    int need;
    unsigned lo, hi;
    char32_t cp;
};

// The lead byte b0 (not ASCII) read; false for a byte that cannot start a sequence.
bool read_lead(unsigned char b0, Lead& l) {
    if (b0 >= 0xc2 && b0 <= 0xdf)
        l = {1, 0x80, 0xbf, char32_t(b0 & 0x1f)};
    else if (b0 == 0xe0)
        l = {2, 0xa0, 0xbf, 0};
    else if ((b0 >= 0xe1 && b0 <= 0xec) || b0 == 0xee || b0 == 0xef)
        l = {2, 0x80, 0xbf, char32_t(b0 & 0x0f)};
    else if (b0 == 0xed)
        l = {2, 0x80, 0x9f, 0xd};
    else if (b0 == 0xf0)
        l = {3, 0x90, 0xbf, 0};
    else if (b0 >= 0xf1 && b0 <= 0xf3)
        l = {3, 0x80, 0xbf, char32_t(b0 & 0x07)};
    else if (b0 == 0xf4)
        l = {3, 0x80, 0x8f, 4};
    else
        return false;
    return true;
}

}  // namespace

// Replacement follows the "maximal subpart" practice (Unicode ch. 3, U+FFFD substitution; WHATWG
// Encoding): a lead byte followed by fewer valid continuation bytes than it needs yields one U+FFFD
// for the bytes consumed so far; a byte that cannot start a sequence yields one U+FFFD on its own.
std::u32string decode_utf8(std::string_view s) {
    std::u32string out;
    out.reserve(s.size());
    const std::size_t n = s.size();
    std::size_t i = 0;
    while (i < n) {
        const auto b0 = static_cast<unsigned char>(s[i]);
        Lead l;
        if (b0 < 0x80 || !read_lead(b0, l)) {
            out.push_back(b0 < 0x80 ? char32_t(b0) : U'\uFFFD');
            ++i;
            continue;
        }
        std::size_t j = i + 1;
        bool ok = true;
        for (int k = 0; k < l.need; ++k) {
            const unsigned b = j < n ? static_cast<unsigned char>(s[j]) : 0u;
            if (j >= n || b < l.lo || b > l.hi) {
                ok = false;
                break;
            }
            l.cp = (l.cp << 6) | (b & 0x3f);
            ++j;
            l.lo = 0x80;
            l.hi = 0xbf;
        }
        out.push_back(ok ? l.cp : U'\uFFFD');
        i = j;
    }
    return out;
}

}  // namespace casteljau
