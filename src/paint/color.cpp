// Paint stage: CSS colour parsing. (Hex forms only for now; the full CSS syntax follows.)
#include <string>

#include "casteljau/error.hpp"
#include "casteljau/paint.hpp"

namespace casteljau {

Color parse_color(std::string_view text) {
    auto hex = [](char c) -> int {
        if (c >= '0' && c <= '9') return c - '0';
        if (c >= 'a' && c <= 'f') return c - 'a' + 10;
        if (c >= 'A' && c <= 'F') return c - 'A' + 10;
        return -1;
    };
    if (text == "none" || text == "transparent") return Color::transparent();
    if (text.size() == 7 && text[0] == '#') {
        int v[6];
        for (int i = 0; i < 6; ++i)
            if ((v[i] = hex(text[static_cast<std::size_t>(i) + 1])) < 0) goto bad;
        return {std::uint8_t(v[0] * 16 + v[1]), std::uint8_t(v[2] * 16 + v[3]), std::uint8_t(v[4] * 16 + v[5]), 255};
    }
bad:
    throw Error(ErrorKind::Parse, "invalid colour '" + std::string(text) + "': expected #rrggbb");
}

}  // namespace casteljau
