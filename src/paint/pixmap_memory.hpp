// Paint stage, internal: a large pixmap that its maker clears itself. A new Pixmap is transparent:
// when its memory is that of a released pixmap of the same size (core/pixel_memory.hpp), the
// constructor clears it on the calling thread. A maker that clears or covers every row anyway, on
// several threads (render_map: band by band on its workers), takes the memory as it is instead.
// Thread-safety: as Pixmap's constructor.
#pragma once

#include "casteljau/paint.hpp"

namespace casteljau {

struct PixmapMemory {
    // A width x height pixmap, checked and thrown for as Pixmap(width, height), whose pixels are
    // transparent when `zero` comes back true and of any content when it comes back false.
    static Pixmap uncleared(int width, int height, bool& zero);
};

}  // namespace casteljau
