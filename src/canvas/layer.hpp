// Canvas stage, internal: a layer of Canvas::begin_layer(): its pixels and how it goes back into
// what is under it.
#pragma once

#include <cstddef>

#include "casteljau/canvas.hpp"

namespace casteljau {

struct Canvas::Layer {
    Pixmap pixels;
    double opacity;
    BlendMode mode;
    std::size_t saved_depth;  // stack_ size right after begin_layer's save()
};

}  // namespace casteljau
