// Text stage, first step: UTF-8 decoding with U+FFFD for invalid input (include/casteljau/text.hpp).
#include <string>
#include <string_view>

#include "casteljau/text.hpp"

namespace casteljau {

// Replacement follows the "maximal subpart" practice (Unicode ch. 3, U+FFFD substitution; WHATWG
// Encoding): a lead byte followed by fewer valid continuation bytes than it needs yields one U+FFFD
// for the bytes consumed so far; a byte that cannot start a sequence yields one U+FFFD on its own.
// The ranges of the second byte exclude overlong forms, surrogates and values above U+10FFFF.
std::u32string decode_utf8(std::string_view s) {
    std::u32string out;
    out.reserve(s.size());
    const std::size_t n = s.size();
    std::size_t i = 0;
    while (i < n) {
        const auto b0 = static_cast<unsigned char>(s[i]);
        if (b0 < 0x80) {
            out.push_back(b0);
            ++i;
            continue;
        }
        int need;
        unsigned lo = 0x80, hi = 0xbf;
        char32_t cp;
        if (b0 >= 0xc2 && b0 <= 0xdf) {
            need = 1;
            cp = b0 & 0x1f;
        } else if (b0 == 0xe0) {
            need = 2;
            lo = 0xa0;
            cp = 0;
        } else if ((b0 >= 0xe1 && b0 <= 0xec) || b0 == 0xee || b0 == 0xef) {
            need = 2;
            cp = b0 & 0x0f;
        } else if (b0 == 0xed) {
            need = 2;
            hi = 0x9f;
            cp = 0xd;
        } else if (b0 == 0xf0) {
            need = 3;
            lo = 0x90;
            cp = 0;
        } else if (b0 >= 0xf1 && b0 <= 0xf3) {
            need = 3;
            cp = b0 & 0x07;
        } else if (b0 == 0xf4) {
            need = 3;
            hi = 0x8f;
            cp = 4;
        } else {
            out.push_back(U'\uFFFD');
            ++i;
            continue;
        }
        std::size_t j = i + 1;
        bool ok = true;
        for (int k = 0; k < need; ++k) {
            const unsigned b = j < n ? static_cast<unsigned char>(s[j]) : 0u;
            if (j >= n || b < lo || b > hi) {
                ok = false;
                break;
            }
            cp = (cp << 6) | (b & 0x3f);
            ++j;
            lo = 0x80;
            hi = 0xbf;
        }
        out.push_back(ok ? cp : U'\uFFFD');
        i = j;
    }
    return out;
}

}  // namespace casteljau
