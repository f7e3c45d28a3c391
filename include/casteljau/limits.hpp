// casteljau/limits.hpp: the resource limits that bound what untrusted input (SVG, GeoJSON,
// TopoJSON, PNG, JPEG, fonts, path data, style sheets) can make the library allocate or compute,
// readable and settable at run time.
//
// Each field of Limits has a default (the values in README.md "Limits") and a ceiling
// (Limits::ceilings()). Every limit may be lowered to 1 (svg_image_nesting to 0: no SVG document
// drawn inside another); some may be raised to their ceiling. The canvas, path and segment limits
// cannot be raised above their defaults: the raster engine's index and offset types are sized for
// them. A check that fails throws Error(ErrorKind::Limit) (or, where README.md says so, skips the
// rest with a warning); the message names the limit in force.
//
// Scope: process-wide. Thread-safety: current_limits() and set_limits() may be called from any
// thread at any time. Each field is read once per check, so a render running while another thread
// calls set_limits() sees, field by field, either the old or the new value; set them before
// rendering starts when a consistent set matters. Units: pixels, counts and bytes, as named.
#pragma once

#include <cstddef>
#include <cstdint>

#include "casteljau/error.hpp"

namespace casteljau {

struct Limits {
    int canvas_dimension = limits::kMaxCanvasDimension;       // pixels per side of a canvas or image
    long long canvas_pixels = limits::kMaxCanvasPixels;        // pixels of a canvas or image
    std::size_t path_points = limits::kMaxPathPoints;          // points of one path (parsed or stroked)
    std::size_t flattened_segments = limits::kMaxFlattenedSegments;  // line segments of one fill after flattening
    int nesting_depth = limits::kMaxNestingDepth;              // SVG elements, patterns, GeoJSON collections, Canvas layers
    std::size_t svg_elements = 1'000'000;                      // elements drawn per SVG document, each use copy counted
    int svg_image_nesting = 4;                                 // SVG documents drawn as <image> inside SVG documents
    std::size_t svgz_bytes = std::size_t(64) << 20;            // inflated size of an .svgz
    std::size_t css_rules = 10'000;                            // rules of an SVG document's style sheets
    std::size_t svg_text_chars = 100'000;                      // characters of SVG text laid out per document
    long long filter_pixels = 1LL << 24;                       // pixels of one filter region
    std::size_t filter_primitives = 1000;                      // primitives in one filter
    std::size_t map_positions = std::size_t(1) << 27;          // positions read from one GeoJSON/TopoJSON map
    std::size_t dashes = std::size_t(1) << 18;                 // dashes produced from one path
    std::uint64_t font_file_bytes = std::uint64_t(512) << 20;  // size of a font file
    std::size_t png_chunk_bytes = limits::kMaxPngChunkBytes;   // inflated text or ICC chunk of a PNG
    std::uint32_t png_ancillary_chunks = limits::kMaxPngAncillaryChunks;  // text, sPLT and unknown PNG chunks kept
    std::uint64_t jpeg_working_memory = std::uint64_t(512) << 20;  // libjpeg's memory besides the image
    std::size_t canvas_save_depth = 1024;                      // Canvas::save() nesting
    std::size_t text_bytes = std::size_t(16) << 20;            // UTF-8 bytes given to layout_text
    std::uint64_t input_bytes = std::uint64_t(1) << 30;        // one input file or stream read whole (read_file, read_map_file)

    // The highest value each field accepts.
    static Limits ceilings() noexcept;
};

// The limits in force now (a copy).
Limits current_limits() noexcept;

// Replaces every limit. Throws Error(ErrorKind::InvalidArgument), changing nothing, when a field
// is below its minimum (1, or 0 for svg_image_nesting) or above its ceiling.
void set_limits(const Limits& limits);

// Restores the defaults (Limits{}).
void reset_limits() noexcept;

}  // namespace casteljau
