// Internal (text module): a reader of the COLR version 1 paint graph (OpenType 1.9 'COLR':
// BaseGlyphList, LayerList, ClipList and the paint tables they point to).
//
// FreeType 2.12 as Debian 12 ships it has its COLR v1 API disabled (FT_Get_Color_Glyph_Paint
// answers nothing), so casteljau reads the table itself: every offset and count is checked against
// the table's size, so a malformed table gives fewer paints, never a read outside it. Variable
// paints (the odd formats) are read at their default values; transforms of every kind come out as
// one Affine. Values are in font units (y up), angles in degrees.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "casteljau/geometry.hpp"

namespace casteljau::text_detail {

struct ColrStop {
    double offset = 0;
    std::uint16_t palette_index = 0;
    double alpha = 1;
};

struct ColrColorLine {
    int extend = 0;  // 0 pad, 1 repeat, 2 reflect
    std::vector<ColrStop> stops;
};

// One paint table. `kind` is its format with the variants folded together.
struct ColrPaint {
    enum class Kind { Layers, Solid, Linear, Radial, Sweep, Glyph, ColrGlyph, Transform, Composite, Unknown };
    Kind kind = Kind::Unknown;
    std::uint32_t first_layer = 0, layer_count = 0;  // Layers
    std::uint16_t palette_index = 0;                 // Solid
    double alpha = 1;                                // Solid
    ColrColorLine line;                              // gradients
    Point p0, p1, p2;                                // Linear; Radial: centres p0, p1; Sweep: centre p0
    double r0 = 0, r1 = 0;                           // Radial
    double start_angle = 0, end_angle = 0;           // Sweep, degrees counter-clockwise from +x
    std::uint16_t glyph = 0;                         // Glyph, ColrGlyph
    Affine transform;                                // Transform: child space -> parent space
    std::size_t child = 0;                           // Glyph, Transform: the child paint; Composite: source
    std::size_t backdrop = 0;                        // Composite
    int mode = 3;                                    // Composite: the COLR composite mode (3 = src-over)
};

class ColrTable {
public:
    // Reads the table's header; an empty table, or one that is not version 1, has no paints.
    explicit ColrTable(std::vector<std::uint8_t> bytes);

    // The root paint of base glyph `glyph` (an offset into the table), if it has one.
    std::optional<std::size_t> root(std::uint32_t glyph) const;
    // Reads the paint at `at`; false when it is out of bounds or malformed.
    bool paint(std::size_t at, ColrPaint& out) const;
    // The paint of layer `index` of the LayerList.
    std::optional<std::size_t> layer(std::uint32_t index) const;
    // The ClipBox of base glyph `glyph` (font units), if any.
    std::optional<Rect> clip_box(std::uint32_t glyph) const;

private:
    std::vector<std::uint8_t> data_;
    std::size_t base_list_ = 0, layer_list_ = 0, clip_list_ = 0;  // offsets, 0: absent
};

}  // namespace casteljau::text_detail
