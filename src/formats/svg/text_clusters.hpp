// Internal (formats): the clusters of SVG text layout (text_layout.cpp) and how vertical text
// places them (text_vertical.cpp).
//
// Coordinates: a cluster's space has its origin on the baseline at the pen, x along the advance,
// y down, in user units of the <text> element.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "casteljau/font.hpp"
#include "casteljau/geometry.hpp"
#include "formats/svg/text_layout.hpp"

namespace casteljau::svg_text {

// One glyph of a cluster.
struct Glyph {
    const Font* font = nullptr;
    std::uint32_t id = 0;
    double x_off = 0, y_off = 0;  // px from the cluster origin, y down
};

// The glyphs of one or more characters that shaping keeps together, and where they go.
struct Cluster {
    std::size_t ch = 0, nch = 1;  // characters (global indices)
    std::size_t span = 0;
    std::vector<Glyph> glyphs;
    double advance = 0;
    double x = 0, y = 0;            // origin on the baseline (before baseline offsets)
    double step = 0;                // distance to the next cluster's origin (advance + spacing)
    double scale_x = 1;             // lengthAdjust="spacingAndGlyphs"
    bool upright = false;           // vertical text: drawn upright (else turned 90 degrees clockwise)
    const Font* font = nullptr;     // metrics for baselines and decorations
    const Font* primary = nullptr;  // the span's first font: decorations of vertical text
};

// Whether character c is set upright in vertical text (else turned sideways).
bool is_upright(char32_t c);

// Cluster space -> user space for cluster `g` of vertical text not on a path, `shift` its
// baseline shift (px, positive up in the horizontal frame).
Affine vertical_cluster_transform(const TextInput& in, const Cluster& g, double shift);

// Vertical text on a path, as resvg lays it out: the clusters follow the path as horizontal
// text does, each cluster's em box centred on the path, upright clusters turned 90 degrees
// counterclockwise about the middle of their advance. What follows the placement on the path.
Affine vertical_on_path(const TextInput& in, const Cluster& g);

// The frames of the decoration lines of vertical text, as resvg draws them (the specifications
// leave them open): a line runs on in the frame of the first cluster of its span and of the
// run of clusters that no dx, dy or rotate moves; that frame is moved like the first cluster's
// baseline (a sideways cluster's is centred on the line, an upright one's is not).
class VerticalDecorationFrames {
public:
    // The frame of cluster `g`'s decorations: x along the line, y down across it.
    Affine frame(const TextInput& in, const Cluster& g, double shift);
    // A new chunk starts a new line.
    void next_chunk() { span_ = static_cast<std::size_t>(-1); }

private:
    std::size_t span_ = static_cast<std::size_t>(-1);
    bool centred_ = false;
};

}  // namespace casteljau::svg_text
