// casteljau/limits.hpp: every limit of the library: the resource limits that bound what untrusted
// input (SVG, GeoJSON, TopoJSON, PNG, JPEG, GIF, WebP, fonts, path data, style sheets) can make
// the library allocate or compute, fixed (namespace limits, compile-time constants) or readable
// and settable at run time (Limits).
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

// Fixed limits. The canvas, path, segment, nesting and PNG values are also the defaults of the
// run-time limits below (Limits); the canvas, path and segment values are their ceilings too.
// README.md "Limits" lists them all.
namespace limits {
// Canvas, path and raster.
inline constexpr int kMaxCanvasDimension = 32768;               // pixels per side
inline constexpr long long kMaxCanvasPixels = 268435456LL;      // 2^28 pixels = 1 GiB of RGBA8
inline constexpr std::size_t kMaxPathPoints = 1u << 24;         // points in one Path
inline constexpr std::size_t kMaxFlattenedSegments = 1u << 23;  // line segments after flattening (~340 MB of edges)
inline constexpr int kMaxFlattenDepth = 16;                     // subdivision depth per curve
inline constexpr double kMaxCoordinate = 1e15;                  // |coordinate| after transform
inline constexpr int kMaxArcPieces = 256;                       // cubics per elliptical arc, at most
inline constexpr int kMaxNestingDepth = 64;                     // SVG element / group nesting (default)

// Curves and surfaces.
// Highest Bézier degree accepted (65 control points). De Casteljau is stable far beyond this; the
// limit keeps the O(n^2) stack buffers small and binomial coefficients (C(64, 32) ~ 1.8e18) finite.
inline constexpr int kMaxBezierDegree = 64;
// Deepest subdivision when approximating a higher-degree curve by cubics (2^16 pieces at most).
inline constexpr int kMaxCubicApproxDepth = 16;
inline constexpr int kMaxSplineDegree = 64;
inline constexpr std::size_t kMaxSplinePoints = 1u << 20;
inline constexpr std::size_t kMaxSurfacePoints = 1u << 20;
inline constexpr int kMaxGridLines = 4096;  // iso curves per direction
inline constexpr std::size_t kMaxShadedQuads = 1u << 20;

// Filters.
inline constexpr int kMaxConvolveOrder = 64;         // feConvolveMatrix order per axis
inline constexpr double kMaxFilterDeviation = 1000;  // blur standard deviation in device pixels (larger is clamped)
inline constexpr long long kMaxConvolveWork = 1LL << 31;  // feConvolveMatrix kernel taps x region pixels

// Text. Largest font size (pixels per em) the text functions accept. Larger sizes would make
// single glyph masks of hundreds of megabytes; draw huge text through a Canvas transform instead.
inline constexpr double kMaxFontSize = 10000.0;
// Largest SVG font-size (user units) drawn; text with a larger one is skipped with a warning.
inline constexpr double kMaxSvgFontSize = 1e5;

// Files.
inline constexpr std::size_t kMaxPngChunkBytes = 16u << 20;    // one PNG chunk's data (text, ICC, Exif)
inline constexpr std::uint32_t kMaxPngAncillaryChunks = 1000;  // text, sPLT and unknown chunks kept per PNG
inline constexpr int kMaxTileZoom = 24;                        // zoom levels of a tile pyramid: 0..24
}  // namespace limits

// Run-time limits.
struct Limits {
    int canvas_dimension = limits::kMaxCanvasDimension;              // pixels per side of a canvas or image
    long long canvas_pixels = limits::kMaxCanvasPixels;              // pixels of a canvas or image
    std::size_t path_points = limits::kMaxPathPoints;                // points of one path (parsed or stroked)
    std::size_t flattened_segments = limits::kMaxFlattenedSegments;  // line segments of one fill after flattening
    int nesting_depth = limits::kMaxNestingDepth;      // SVG elements, patterns, GeoJSON collections, Canvas layers
    std::size_t svg_elements = 1'000'000;              // elements drawn per SVG document, each use copy counted
    int svg_image_nesting = 4;                         // SVG documents drawn as <image> inside SVG documents
    std::size_t svgz_bytes = std::size_t(64) << 20;    // inflated size of an .svgz
    std::size_t css_rules = 10'000;                    // rules of an SVG document's style sheets
    std::size_t svg_text_chars = 100'000;              // characters of SVG text laid out per document
    long long filter_pixels = 1LL << 24;               // pixels of one filter region
    std::size_t filter_primitives = 1000;              // primitives in one filter
    std::size_t map_positions = std::size_t(1) << 27;  // positions read from one GeoJSON/TopoJSON map
    std::size_t dashes = std::size_t(1) << 18;         // dashes produced from one path
    std::uint64_t font_file_bytes = std::uint64_t(512) << 20;             // size of a font file
    std::size_t png_chunk_bytes = limits::kMaxPngChunkBytes;              // inflated text or ICC chunk of a PNG
    std::uint32_t png_ancillary_chunks = limits::kMaxPngAncillaryChunks;  // text, sPLT and unknown PNG chunks kept
    std::uint64_t jpeg_working_memory = std::uint64_t(512) << 20;         // libjpeg's memory besides the image
    std::size_t canvas_save_depth = 1024;                                 // Canvas::save() nesting
    std::size_t text_bytes = std::size_t(16) << 20;                       // UTF-8 bytes given to layout_text
    std::uint64_t input_bytes = std::uint64_t(1)
                                << 30;  // one input file or stream read whole (read_file, read_map_file)
    // Piece visits the exact cells of one fill may spend, besides 2000 per segment (raster.hpp,
    // RasterStats::dense_cells): past it, such cells are integrated on lines instead.
    std::uint64_t exact_work = 50'000'000;

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
