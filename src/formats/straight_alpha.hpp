// Formats stage (internal): decoders that receive straight (non-premultiplied) RGBA rows turn
// them into the Pixmap's premultiplied form in place.
// Thread-safety: a pure function of its argument.
#pragma once

#include "casteljau/paint.hpp"

namespace casteljau::formats_detail {

// Premultiplies every pixel of `pixmap`, read as straight RGBA (opaque pixels stay as they are).
inline void premultiply_in_place(Pixmap& pixmap) {
    for (int y = 0; y < pixmap.height(); ++y) {
        std::uint8_t* p = pixmap.row(y);
        for (int x = 0; x < pixmap.width(); ++x, p += 4) {
            if (p[3] == 255) continue;
            const PremulPixel q = premultiply(Color{p[0], p[1], p[2], p[3]});
            p[0] = q.r;
            p[1] = q.g;
            p[2] = q.b;
            p[3] = q.a;
        }
    }
}

}  // namespace casteljau::formats_detail
