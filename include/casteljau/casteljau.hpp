// casteljau/casteljau.hpp: every public C++ header, for programs that use the whole library.
//
// The pipeline, in the order a fill walks it:
//   source (SVG path data, SVG file, curves, font glyphs, GeoJSON/TopoJSON maps) -> Path (path.hpp)
//   -> Affine to pixel space (geometry.hpp) -> flatten by recursive de Casteljau (flatten.hpp)
//   -> clipped edges -> exact-area coverage (raster.hpp) -> composite onto a Pixmap (canvas.hpp,
//   paint.hpp) -> PNG (png.hpp). Stroking (stroke.hpp) is a Path -> Path step before the fill.
//
// Thread-safety: see each header. Objects (Path, Rasterizer, Canvas, Font, GlyphCache, ...) hold
// their own state; distinct objects may be used from distinct threads at once. The state shared by
// the whole process is this, and nothing else:
//   - the resource limits (limits.hpp): set_limits() / current_limits(), from any thread at any
//     time (each field is read once per check);
//   - the thread pool (threads.hpp): set_thread_count(), from any thread but not from inside a
//     callback casteljau runs;
//   - kept rasterizer states (raster.hpp): a destroyed Rasterizer's buffers (at most 8, trimmed)
//     wait behind a lock for the next Rasterizer; nothing to set;
//   - per-thread scratch buffers of classify_topology (raster.hpp), kept until the thread ends;
//   - the SIMD instruction set of the raster kernels, chosen from the CPU on first use;
//   - PROJ, SQLite and ICU, opened once on first use (projections that are not built in; MBTiles;
//     line breaking of wrapped text) and kept open;
//   - system font fallback (text.hpp, TextStyle::system_fonts; SVG text with
//     SvgOptions::system_fallback, shaping.hpp's SystemFontFallback): fontconfig's configuration,
//     read when a text first needs a font its chain lacks, the sorted face lists of each query and
//     the face chosen for each character cluster, kept behind a lock until the process ends; off
//     with system_fonts = false (system_fallback = false).
// Each Font owns its FreeType and HarfBuzz objects, and glyph masks are cached in GlyphCache
// objects the caller owns (text.hpp).
#pragma once

#include "casteljau/arc.hpp"
#include "casteljau/bezier.hpp"
#include "casteljau/blend_mode.hpp"
#include "casteljau/canvas.hpp"
#include "casteljau/error.hpp"
#include "casteljau/figures.hpp"
#include "casteljau/file_io.hpp"
#include "casteljau/filter.hpp"
#include "casteljau/flatten.hpp"
#include "casteljau/font.hpp"
#include "casteljau/font_database.hpp"
#include "casteljau/geojson.hpp"
#include "casteljau/geometry.hpp"
#include "casteljau/image.hpp"
#include "casteljau/limits.hpp"
#include "casteljau/map.hpp"
#include "casteljau/nurbs.hpp"
#include "casteljau/paint.hpp"
#include "casteljau/path.hpp"
#include "casteljau/png.hpp"
#include "casteljau/projection.hpp"
#include "casteljau/raster.hpp"
#include "casteljau/round_stroke.hpp"
#include "casteljau/seamless.hpp"
#include "casteljau/shader.hpp"
#include "casteljau/shaping.hpp"
#include "casteljau/spline.hpp"
#include "casteljau/stroke.hpp"
#include "casteljau/surface.hpp"
#include "casteljau/svg.hpp"
#include "casteljau/svg_path.hpp"
#include "casteljau/text.hpp"
#include "casteljau/threads.hpp"
#include "casteljau/tiles.hpp"
#include "casteljau/vec.hpp"
