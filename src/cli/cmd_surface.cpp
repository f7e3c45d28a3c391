// casteljau surface: draw a tensor-product surface (Bézier patch, B-spline or NURBS surface) read
// from JSON as a projected iso-parameter grid, optionally with shaded quads.
//
//   casteljau surface examples/data/patch.json --render hill.png --projection cabinet --grid 12 --shaded
//
// File format: {"degree": [m, n], "points": [[[x, y, z], ...], ...]}: (m + 1) rows (the u index) of
// (n + 1) points for a Bézier patch. Optional "type": "bezier" (default), "bspline" or "nurbs"; for
// the spline kinds the rows may hold any count >= degree + 1, "knots_u"/"knots_v" default to clamped
// knots, and "nurbs" takes "weights": [[w, ...], ...] shaped like "points" (default all 1).
// Coordinates: y down as given, z recedes (surface.hpp). Exit status 1: unreadable file, malformed
// JSON, wrong counts or shapes; 2: bad usage (unknown projection, grid outside 2..4096).
#include <simdjson.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "casteljau/figures.hpp"
#include "casteljau/limits.hpp"
#include "casteljau/png.hpp"
#include "casteljau/spline.hpp"
#include "casteljau/surface.hpp"
#include "cli/cli.hpp"

namespace casteljau::cli {

namespace {

struct SurfaceOptions {
    std::string file, render, projection = "oblique", size = "400x400";
    int grid = 10;
    bool shaded = false;
};

[[noreturn]] void bad(const std::string& path, const std::string& what, ErrorKind kind = ErrorKind::InvalidData) {
    throw Error(kind, path + ": " + what);
}

double number(const simdjson::dom::element& e, const std::string& path, const std::string& where) {
    double v = 0;
    if (e.get_double().get(v) != simdjson::SUCCESS || !std::isfinite(v))
        bad(path, where + " is not a finite number", ErrorKind::Parse);
    return v;
}

std::vector<double> numbers(const simdjson::dom::element& e, const std::string& path, const std::string& member) {
    simdjson::dom::array arr;
    if (e.get_array().get(arr) != simdjson::SUCCESS)
        bad(path, "\"" + member + "\" must be an array of numbers", ErrorKind::Parse);
    std::vector<double> out;
    for (simdjson::dom::element x : arr) out.push_back(number(x, path, "\"" + member + "\" entry"));
    return out;
}

// A rectangular array of rows; `leaf` converts each entry. Returns rows x cols values row-major.
template <class T, class F>
std::vector<T> grid_of(const simdjson::dom::element& e, const std::string& path, const std::string& member,
                       std::size_t& rows, std::size_t& cols, F leaf) {
    simdjson::dom::array outer;
    if (e.get_array().get(outer) != simdjson::SUCCESS)
        bad(path, "\"" + member + "\" must be an array of rows", ErrorKind::Parse);
    std::vector<T> out;
    rows = 0;
    cols = 0;
    for (simdjson::dom::element row : outer) {
        simdjson::dom::array inner;
        if (row.get_array().get(inner) != simdjson::SUCCESS)
            bad(path, "\"" + member + "\" row " + std::to_string(rows) + " must be an array", ErrorKind::Parse);
        std::size_t c = 0;
        for (simdjson::dom::element x : inner) {
            out.push_back(leaf(x, member + "[" + std::to_string(rows) + "][" + std::to_string(c) + "]"));
            ++c;
        }
        if (rows == 0)
            cols = c;
        else if (c != cols)
            bad(path, "\"" + member + "\" row " + std::to_string(rows) + " has " + std::to_string(c) +
                          " entries, row 0 has " + std::to_string(cols));
        ++rows;
        if (out.size() > limits::kMaxSurfacePoints) bad(path, "too many points", ErrorKind::Limit);
    }
    if (rows == 0 || cols == 0) bad(path, "\"" + member + "\" is empty");
    return out;
}

// "type": bezier (the default), bspline or nurbs.
std::string surface_type(const simdjson::dom::object& obj, const std::string& path) {
    simdjson::dom::element e;
    if (obj["type"].get(e) != simdjson::SUCCESS) return "bezier";
    std::string_view t;
    if (e.get_string().get(t) != simdjson::SUCCESS) bad(path, "\"type\" must be a string", ErrorKind::Parse);
    std::string type(t);
    if (type != "bezier" && type != "bspline" && type != "nurbs")
        bad(path, "\"type\" must be \"bezier\", \"bspline\" or \"nurbs\", got \"" + type + "\"");
    return type;
}

// "degree": [m, n], each an integer 1..64.
std::pair<int, int> surface_degree(const simdjson::dom::object& obj, const std::string& path) {
    simdjson::dom::element e;
    if (obj["degree"].get(e) != simdjson::SUCCESS) bad(path, "missing \"degree\": [m, n]");
    const std::vector<double> deg = numbers(e, path, "degree");
    if (deg.size() != 2 || deg[0] != std::floor(deg[0]) || deg[1] != std::floor(deg[1]) || deg[0] < 1 || deg[1] < 1 ||
        deg[0] > 64 || deg[1] > 64)
        bad(path, "\"degree\" must be two integers [m, n], each 1..64");
    return {static_cast<int>(deg[0]), static_cast<int>(deg[1])};
}

// "points": rows of [x, y, z] control points, all rows of one length.
std::vector<Point3> control_net(const simdjson::dom::object& obj, const std::string& path, std::size_t& rows,
                                std::size_t& cols) {
    simdjson::dom::element e;
    if (obj["points"].get(e) != simdjson::SUCCESS) bad(path, "missing \"points\"");
    return grid_of<Point3>(e, path, "points", rows, cols,
                           [&](const simdjson::dom::element& x, const std::string& where) {
                               const std::vector<double> c = numbers(x, path, where);
                               if (c.size() != 3) bad(path, where + " must be [x, y, z]");
                               return Point3{c[0], c[1], c[2]};
                           });
}

// A knot vector member, or the clamped knots of `degree` over `count` control points.
std::vector<double> knots_or_clamped(const simdjson::dom::object& obj, const std::string& path, const char* member,
                                     int degree, std::size_t count) {
    simdjson::dom::element e;
    if (obj[member].get(e) == simdjson::SUCCESS) return numbers(e, path, member);
    return clamped_knots(degree, count);
}

// "weights": a grid of the points' shape; all 1 when absent.
std::vector<double> weight_grid(const simdjson::dom::object& obj, const std::string& path, std::size_t rows,
                                std::size_t cols) {
    simdjson::dom::element e;
    if (obj["weights"].get(e) != simdjson::SUCCESS) return std::vector<double>(rows * cols, 1.0);
    std::size_t wr = 0, wc = 0;
    std::vector<double> w = grid_of<double>(
        e, path, "weights", wr, wc,
        [&](const simdjson::dom::element& x, const std::string& where) { return number(x, path, where); });
    if (wr != rows || wc != cols) bad(path, "\"weights\" must have the shape of \"points\"");
    return w;
}

void run(const SurfaceOptions& o) {
    const std::string& path = o.file;
    const std::string text = read_text_input(path);
    simdjson::dom::parser parser;
    simdjson::dom::element doc;
    const simdjson::padded_string padded(text);
    if (const auto err = parser.parse(padded).get(doc); err != simdjson::SUCCESS)
        bad(path, std::string("invalid JSON: ") + simdjson::error_message(err), ErrorKind::Parse);
    simdjson::dom::object obj;
    if (doc.get_object().get(obj) != simdjson::SUCCESS)
        bad(path, "the top level must be a JSON object", ErrorKind::Parse);
    const std::string type = surface_type(obj, path);
    const auto [m, n] = surface_degree(obj, path);
    std::size_t rows = 0, cols = 0;
    std::vector<Point3> net = control_net(obj, path, rows, cols);

    SurfaceDrawing d;
    d.projection = o.projection == "ortho"     ? Projection::Orthographic
                   : o.projection == "cabinet" ? Projection::Cabinet
                                               : Projection::Cavalier;
    d.grid = o.grid;
    d.shaded = o.shaded;
    FigureOptions fo;
    parse_size_option("--size", o.size, fo.width, fo.height);
    fo.margin = std::min(24.0, std::min(fo.width, fo.height) / 10.0);

    if (type == "bezier") {
        if (rows != static_cast<std::size_t>(m + 1) || cols != static_cast<std::size_t>(n + 1))
            bad(path, "a degree [" + std::to_string(m) + ", " + std::to_string(n) + "] patch needs " +
                          std::to_string(m + 1) + " rows of " + std::to_string(n + 1) + " points, got " +
                          std::to_string(rows) + " rows of " + std::to_string(cols));
        write_png(draw_surface_figure(BezierPatch<Point3>(m, n, std::move(net)), d, fo).image, o.render);
        return;
    }
    std::vector<double> ku = knots_or_clamped(obj, path, "knots_u", m, rows);
    std::vector<double> kv = knots_or_clamped(obj, path, "knots_v", n, cols);
    if (type == "bspline") {
        const BSplineSurface<Point3> s(m, n, rows, cols, std::move(net), std::move(ku), std::move(kv));
        write_png(draw_surface_figure(s, d, fo).image, o.render);
        return;
    }
    std::vector<double> w = weight_grid(obj, path, rows, cols);
    const NurbsSurface<Point3> s(m, n, rows, cols, std::move(net), std::move(w), std::move(ku), std::move(kv));
    write_png(draw_surface_figure(s, d, fo).image, o.render);
}

}  // namespace

void register_surface(CLI::App& app) {
    auto o = std::make_shared<SurfaceOptions>();
    CLI::App* sub = app.add_subcommand(
        "surface",
        "Draw a Bezier patch (or B-spline / NURBS surface) from JSON as a projected grid of iso-parameter curves.\n"
        "File: {\"degree\": [m, n], \"points\": [[[x, y, z], ...], ...]} with m+1 rows of n+1 points; optional "
        "\"type\":\n"
        "\"bspline\"/\"nurbs\" with \"knots_u\", \"knots_v\" (default clamped) and \"weights\" (rows like points).\n"
        "y is down, z recedes. Exit status 1: bad data; 2: bad usage.");
    sub->add_option("file", o->file, "Surface JSON file ('-' reads stdin)")->required();
    sub->add_option("--render", o->render, "Output PNG file")->required();
    sub->add_option("--projection", o->projection, "oblique (cavalier, default), cabinet or ortho")
        ->check(CLI::IsMember({"oblique", "cavalier", "cabinet", "ortho"}));
    sub->add_option("--grid", o->grid, "Iso-parameter curves per direction, 2..4096 (default 10)")
        ->check(CLI::Range(2, limits::kMaxGridLines));
    sub->add_flag("--shaded", o->shaded, "Fill Lambert-shaded quads back to front under the grid");
    sub->add_option("--size", o->size, "Canvas WxH in pixels (default 400x400)");
    sub->callback([o]() { run(*o); });
}

}  // namespace casteljau::cli
