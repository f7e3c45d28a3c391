// Shared input/output helpers for the curve commands (cmd_bezier.cpp, cmd_spline.cpp): point lists
// from the command line or a JSON file, number lists, and the number format of their output.
//
// Output format: every number is printed with 12 significant digits (printf %.12g, which drops
// trailing zeros), after snapping values whose magnitude is below 1e-12 x the largest input
// coordinate to 0 (rounding noise such as 2.8e-14 where the exact answer is 0), and "-0" prints as
// "0". So the textbook cubic at t = 0.4 prints exactly "69.12 80.64". Points print as "x y" (or
// "x y z" for 3-D input), one per line; separate curves are separated by an empty line.
#pragma once

#include <string>
#include <vector>

#include "casteljau/vec.hpp"

namespace casteljau::cli {

// Points of 2 or 3 coordinates (all the same); 2-D points have z = 0.
struct PointList {
    int dimension = 2;
    std::vector<Point3> points;

    std::vector<Point> as_2d() const;
    const std::vector<Point3>& as_3d() const { return points; }
    // Largest |coordinate| (the scale for snapping output noise).
    double scale() const;
};

// "x,y x,y ..." or "x,y,z ..." (points separated by whitespace or ';'). Throws UsageError naming
// `option` for malformed text, mixed dimensions or non-finite numbers.
PointList parse_points_option(const std::string& option, const std::string& text);
// Numbers separated by whitespace or commas; throws UsageError naming `option`.
std::vector<double> parse_numbers_option(const std::string& option, const std::string& text);

// The fields a curve JSON file may hold: {"points": [[x, y], ...], "tangents": [[x, y], ...],
// "weights": [w, ...], "knots": [u, ...], "degree": p}. Missing members are empty / -1.
struct CurveFile {
    PointList points;
    PointList tangents;
    std::vector<double> weights;
    std::vector<double> knots;
    int degree = -1;
};
// Reads and parses `path` ("-" is standard input). Throws Error(Io) if unreadable and Error(Parse)
// for malformed JSON or members of the wrong shape.
CurveFile read_curve_file(const std::string& path);

std::string format_number(double v, double scale);
std::string format_point(const Point& p, double scale);
std::string format_point(const Point3& p, double scale, int dimension);

// A parsed point as the point type of a 2-D or 3-D curve, and back (2-D points have z = 0).
template <CurvePoint P>
P to_point(const Point3& p) {
    if constexpr (std::same_as<P, Point>)
        return {p.x, p.y};
    else
        return p;
}
inline Point3 to_p3(const Point& p) { return {p.x, p.y, 0}; }
inline Point3 to_p3(const Point3& p) { return p; }

}  // namespace casteljau::cli
