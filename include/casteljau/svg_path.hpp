// casteljau/svg_path.hpp: SVG path data (the `d` attribute) to Path and back; SVG `points` lists.
//
// Parsing covers the complete SVG 1.1 / SVG 2 path grammar: M m L l H h V v C c S s Q q T t A a Z z,
// implicit repetition of the last command (after M / m the extra pairs are L / l), numbers as in
// `1e-3`, `1E+5`, `.5.5` (two numbers), `-1-2`, `+3`, `1.`, whitespace (space, tab, CR, LF, FF) and
// at most one comma between numbers, arc flags written without separators (`a1 1 0 00 1 1`).
// Semantics follow SVG 2: S / T reflect the previous control point only when the previous command
// was C/c/S/s resp. Q/q/T/t (otherwise the current point is used); after Z the next command starts
// at the subpath's start; arcs follow SVG 2 F.6 and become cubics (see casteljau/arc.hpp for the
// error bound; SvgPathOptions::arc_tolerance chooses it). Numbers that underflow read as 0.
//
// Deliberate choices:
// - Empty or all-whitespace data gives an empty Path, not an error (SVG: such a path renders nothing).
// - Path data must start with M or m (error at column 1 otherwise).
// - Negative arc radii are taken as their absolute values (SVG 2 F.6.6), not rejected.
// - Errors: parse_svg_path throws Error(ErrorKind::Parse) with a message like
//   "path data column 17: expected a number after 'L', found 'x'" (columns count characters from 1;
//   multi-byte UTF-8 counts as one). A number that overflows double (1e400), or a relative or
//   reflected coordinate that does, is "path data column N: number out of range". More points than
//   SvgPathOptions::max_points (at most Limits::path_points) is Error(ErrorKind::Limit).
//   SVG itself asks renderers to draw the path up to the first error; parse_svg_path_lenient does
//   that (the result holds every segment that was complete before the error, as browsers and resvg
//   draw it) and reports the message instead of throwing.
// Coordinates are the path data's own user units; nothing is flipped.
// Thread-safety: free functions without shared state.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "casteljau/arc.hpp"
#include "casteljau/error.hpp"
#include "casteljau/limits.hpp"
#include "casteljau/path.hpp"

namespace casteljau {

struct SvgPathOptions {
    // Maximum distance in path units between an arc's cubics and the true ellipse (casteljau/arc.hpp).
    double arc_tolerance = kDefaultArcTolerance;
    // Points the resulting Path may hold; values above Limits::path_points count as that limit.
    std::size_t max_points = limits::kMaxPathPoints;
};

// Parses SVG path data. Throws Error(Parse) with the column (see above), Error(Limit) beyond
// max_points, Error(InvalidArgument) for an arc_tolerance that is not > 0.
Path parse_svg_path(std::string_view d, const SvgPathOptions& options = {});

// Parses SVG path data up to the first error and returns what was complete before it (the whole
// path when there is no error). When `error` is given, it receives the error message, or is cleared.
Path parse_svg_path_lenient(std::string_view d, std::string* error = nullptr, const SvgPathOptions& options = {});

// Formats a Path as compact absolute SVG path data (M L H V C S Q T Z, repeated commands omitted,
// numbers in the shortest form that reads back to the same double). For every Path without conics,
// parse_svg_path(format_svg_path(p)) == p exactly, every coordinate identical to the bit (-0 included). Conics have no SVG form: each is written as cubics
// within 1e-9 of the conic, relative to the size of its control polygon (the largest distance between
// its control points), measured as the distance from sample points of the cubics to the conic.
// Throws Error(InvalidArgument) for a path with a non-finite coordinate.
std::string format_svg_path(const Path& path);

// Parses an SVG `points` list (polyline / polygon): "x,y x,y ...", the same number and separator
// rules as path data. Gives a move to the first point and lines to the others, closed when `close`
// (polygon). Empty or all-whitespace gives an empty Path. An odd count of numbers or a malformed
// number throws Error(Parse) with a message like "points column 8: expected a number (y of point 2),
// found end of data".
Path parse_points(std::string_view points, bool close = false);

// As parse_points, but returns the points up to the first error (closed when `close`: SVG renders a
// polygon in error up to the error) and reports the message instead of throwing.
Path parse_points_lenient(std::string_view points, bool close = false, std::string* error = nullptr);

}  // namespace casteljau
