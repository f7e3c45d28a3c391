// casteljau/casteljau.hpp: everything, for programs that use the whole library.
//
// The pipeline, in the order a fill walks it:
//   source (SVG path data, SVG file, curves, font glyphs) -> Path (path.hpp)
//   -> Affine to pixel space (geometry.hpp) -> flatten by recursive de Casteljau (flatten.hpp)
//   -> clipped edges -> exact-area coverage (raster.hpp) -> composite onto a Pixmap (canvas.hpp,
//   paint.hpp) -> PNG (png.hpp). Stroking (stroke.hpp) is a Path -> Path step before the fill.
// Thread-safety: see each header; no global mutable state anywhere.
#pragma once

#include "casteljau/arc.hpp"
#include "casteljau/bezier.hpp"
#include "casteljau/canvas.hpp"
#include "casteljau/shader.hpp"
#include "casteljau/error.hpp"
#include "casteljau/filter.hpp"
#include "casteljau/flatten.hpp"
#include "casteljau/limits.hpp"
#include "casteljau/geometry.hpp"
#include "casteljau/nurbs.hpp"
#include "casteljau/paint.hpp"
#include "casteljau/path.hpp"
#include "casteljau/png.hpp"
#include "casteljau/raster.hpp"
#include "casteljau/spline.hpp"
#include "casteljau/stroke.hpp"
#include "casteljau/surface.hpp"
#include "casteljau/svg.hpp"
#include "casteljau/svg_path.hpp"
#include "casteljau/threads.hpp"
#include "casteljau/vec.hpp"
