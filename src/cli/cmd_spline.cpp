// casteljau spline: B-splines, NURBS and interpolating splines (Hermite, Cardinal, Catmull-Rom,
// Kochanek-Bartels, natural cubic), converted to Bézier pieces or evaluated.
//
//   casteljau spline --kind bspline --points "0,0 10,20 30,20 40,0" --degree 2 --to-bezier
//   casteljau spline --kind catmull-rom --points "0,0 10,10 20,0 30,10" --to-bezier
//   casteljau spline --kind nurbs --points-file arc.json --eval 0.5
//   casteljau spline --kind bspline --points "..." --render s.png --basis basis.png
//
// Pieces print one after another, separated by an empty line; NURBS pieces print "x y w" (the
// weight last). Parameters: B-splines and NURBS use their knot domain; interpolating splines use
// T in [0, pieces], piece floor(T) at local parameter T - floor(T).
// Output format: curve_args.hpp. Exit status 1: bad data; 2: bad usage.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <sstream>

#include "casteljau/figures.hpp"
#include "casteljau/nurbs.hpp"
#include "casteljau/png.hpp"
#include "casteljau/spline.hpp"
#include "cli/cli.hpp"
#include "cli/curve_args.hpp"

namespace casteljau::cli {

namespace {

struct SplineOptions {
    std::string kind, points, points_file, knots, knot_type = "clamped", weights, tangents, ends = "duplicate",
                                                  param = "uniform", render, basis, size = "400x400";
    int degree = 3, derivative = 0;
    double tension = 0, continuity = 0, bias = 0, eval = 0, basis_at = 0;
    CLI::Option *o_points = nullptr, *o_file = nullptr, *o_degree = nullptr, *o_knots = nullptr, *o_knot_type = nullptr,
                *o_weights = nullptr, *o_tangents = nullptr, *o_tension = nullptr, *o_continuity = nullptr,
                *o_bias = nullptr, *o_ends = nullptr, *o_param = nullptr, *o_to_bezier = nullptr, *o_eval = nullptr,
                *o_derivative = nullptr, *o_basis_at = nullptr, *o_render = nullptr, *o_basis = nullptr,
                *o_size = nullptr;
};

FigureOptions figure_options(const SplineOptions& o) {
    FigureOptions fo;
    parse_size_option("--size", o.size, fo.width, fo.height);
    fo.margin = std::min(24.0, std::min(fo.width, fo.height) / 10.0);
    return fo;
}

// --render / --basis for 2-D input (3-D is rejected before this is called).
void render_pictures(const SplineOptions& o, const Path& curve, std::span<const Point> polygon,
                     std::span<const Point> knot_points, int degree, std::span<const double> knots) {
    const FigureOptions fo = figure_options(o);
    if (o.o_render->count()) write_png(draw_spline_figure(curve, polygon, knot_points, fo).image, o.render);
    if (o.o_basis->count()) write_png(draw_basis_figure(degree, knots, fo).image, o.basis);
}

template <CurvePoint P>
std::vector<P> convert(const PointList& l) {
    std::vector<P> v;
    for (const Point3& p : l.points) v.push_back(to_point<P>(p));
    return v;
}

bool is_knot_kind(const std::string& k) { return k == "bspline" || k == "nurbs"; }

// Prints points one per line, at the input's scale and dimension.
template <CurvePoint P>
struct PointPrinter {
    std::ostringstream& out;
    double scale;
    void operator()(const P& p) const { out << format_point(to_p3(p), scale, point_dimension<P>) << '\n'; }
    // A NURBS control point: its coordinates, then its weight.
    void operator()(const P& p, double weight) const {
        out << format_point(to_p3(p), scale, point_dimension<P>) << ' ' << format_number(weight, 0) << '\n';
    }
};

// A B-spline's or NURBS's degree, knots, control points and weights: from the options, else the
// file; knots missing from both are built for --knot-type.
template <CurvePoint P>
struct KnottedInput {
    int degree;
    std::vector<double> knots, weights;
    std::vector<P> ctrl;
};

template <CurvePoint P>
KnottedInput<P> knotted_input(const SplineOptions& o, const CurveFile& file, const std::vector<P>& pts) {
    KnottedInput<P> in{o.o_degree->count() || file.degree < 0 ? o.degree : file.degree,
                       o.o_knots->count() ? parse_numbers_option("--knots", o.knots) : file.knots,
                       o.o_weights->count() ? parse_numbers_option("--weights", o.weights) : file.weights, pts};
    if (!in.knots.empty()) return in;
    if (o.knot_type != "periodic") {
        in.knots = o.knot_type == "uniform" ? uniform_knots(in.degree, in.ctrl.size())
                                            : clamped_knots(in.degree, in.ctrl.size());
        return in;
    }
    // Wrap the control points (and weights) like BSpline::periodic.
    const BSpline<P> per = BSpline<P>::periodic(in.degree, in.ctrl);
    in.ctrl.assign(per.points().begin(), per.points().end());
    in.knots.assign(per.knots().begin(), per.knots().end());
    if (!in.weights.empty()) {
        const std::size_t n = in.weights.size();
        for (std::size_t i = 0; i < static_cast<std::size_t>(in.degree) && n > 0; ++i)
            in.weights.push_back(in.weights[i % n]);
    }
    return in;
}

// What the options ask of a B-spline or NURBS `s`: its pictures (the curve from curve_path(s)),
// its Bezier pieces (print_pieces()), a point or derivative at --eval, or its basis functions at
// --basis-at.
template <CurvePoint P, class Spline, class CurvePath, class PrintPieces>
void report_knotted(const SplineOptions& o, const Spline& s, int degree, const PointPrinter<P>& line,
                    const CurvePath& curve_path, const PrintPieces& print_pieces) {
    if (o.o_render->count() || o.o_basis->count()) {
        if constexpr (std::same_as<P, Point>) {
            std::vector<Point> kp;
            for (double u : s.breakpoints()) kp.push_back(s.eval(u));
            render_pictures(o, curve_path(s), s.points(), kp, degree, s.knots());
        }
    } else if (o.o_to_bezier->count()) {
        print_pieces();
    } else if (o.o_eval->count()) {
        line(s.derivative(o.o_derivative->count() ? o.derivative : 0, o.eval));
    } else {
        for (double b : bspline_basis_all(degree, s.knots(), o.basis_at)) line.out << format_number(b, 1) << '\n';
    }
}

template <CurvePoint P>
void run_knotted(const SplineOptions& o, const CurveFile& file, const std::vector<P>& pts,
                 const PointPrinter<P>& line) {
    KnottedInput<P> in = knotted_input(o, file, pts);
    if (o.kind == "bspline") {
        const BSpline<P> s(in.degree, in.ctrl, in.knots);
        report_knotted(
            o, s, in.degree, line, [](const auto& sp) { return to_path(sp.to_bezier()); },
            [&] {
                const auto pieces = s.to_bezier();
                for (std::size_t j = 0; j < pieces.size(); ++j) {
                    if (j) line.out << '\n';
                    for (const P& p : pieces[j].points()) line(p);
                }
            });
        return;
    }
    if (in.weights.empty()) in.weights.assign(in.ctrl.size(), 1.0);
    const Nurbs<P> s(in.degree, in.ctrl, in.weights, in.knots);
    report_knotted(
        o, s, in.degree, line, [](const auto& sp) { return to_path(sp); },
        [&] {
            const auto pieces = s.to_bezier();
            for (std::size_t j = 0; j < pieces.size(); ++j) {
                if (j) line.out << '\n';
                for (std::size_t i = 0; i < pieces[j].points().size(); ++i)
                    line(pieces[j].points()[i], pieces[j].weights()[i]);
            }
        });
}

// The cubic Bezier pieces of an interpolating spline (--kind hermite, cardinal, catmull-rom, kb or
// natural).
template <CurvePoint P>
std::vector<Bezier<P>> interpolating_pieces(const SplineOptions& o, const CurveFile& file, const std::vector<P>& pts) {
    const EndCondition ends = o.ends == "closed"  ? EndCondition::Closed
                              : o.ends == "inner" ? EndCondition::Inner
                                                  : EndCondition::Duplicate;
    if (o.kind == "hermite") {
        const PointList tl = o.o_tangents->count() ? parse_points_option("--tangents", o.tangents) : file.tangents;
        if (!tl.points.empty() && tl.dimension != file.points.dimension)
            throw UsageError("--tangents must have the same dimension as the points");
        return hermite_spline<P>(pts, convert<P>(tl));
    }
    if (o.kind == "cardinal") return cardinal_spline<P>(pts, o.tension, ends);
    if (o.kind == "catmull-rom") return catmull_rom_spline<P>(pts, ends);
    if (o.kind == "kb") return kochanek_bartels_spline<P>(pts, {o.tension, o.continuity, o.bias}, ends);
    const Parametrization param = o.param == "chord"         ? Parametrization::ChordLength
                                  : o.param == "centripetal" ? Parametrization::Centripetal
                                                             : Parametrization::Uniform;
    return natural_spline<P>(pts, param);
}

// What the options ask of an interpolating spline's pieces: its picture, the pieces, or a point
// or derivative at --eval = T (piece floor(T) at T - floor(T)).
template <CurvePoint P>
void report_pieces(const SplineOptions& o, const std::vector<Bezier<P>>& pieces, const PointPrinter<P>& line) {
    if (o.o_render->count()) {
        if constexpr (std::same_as<P, Point>) {
            std::vector<Point> polygon, joins;
            for (const auto& b : pieces) {
                const auto bp = b.points();
                polygon.insert(polygon.end(), bp.begin() + (polygon.empty() ? 0 : 1), bp.end());
                if (joins.empty()) joins.push_back(b.front());
                joins.push_back(b.back());
            }
            render_pictures(o, to_path(pieces), polygon, joins, 0, {});
        }
    } else if (o.o_to_bezier->count()) {
        for (std::size_t j = 0; j < pieces.size(); ++j) {
            if (j) line.out << '\n';
            for (const P& p : pieces[j].points()) line(p);
        }
    } else {
        const double n = static_cast<double>(pieces.size());
        if (!(o.eval >= 0 && o.eval <= n))
            throw Error(ErrorKind::InvalidArgument,
                        "t = " + format_number(o.eval, 0) + " is outside [0, " + format_number(n, 0) + "]");
        const std::size_t j = std::min(pieces.size() - 1, static_cast<std::size_t>(std::floor(o.eval)));
        const double t = o.eval - static_cast<double>(j);
        line(pieces[j].derivative(o.o_derivative->count() ? o.derivative : 0, t));
    }
}

template <CurvePoint P>
void run(const SplineOptions& o, const CurveFile& file) {
    std::ostringstream out;
    const PointPrinter<P> line{out, file.points.scale()};
    const std::vector<P> pts = convert<P>(file.points);
    if (is_knot_kind(o.kind))
        run_knotted(o, file, pts, line);
    else
        report_pieces(o, interpolating_pieces(o, file, pts), line);
    std::cout << out.str();
}

// Options that apply to some kinds only are usage errors with the others.
void check_kind_options(const SplineOptions& o) {
    const bool knotted = is_knot_kind(o.kind);
    auto only = [&](CLI::Option* opt, bool allowed, const char* kinds) {
        if (opt->count() && !allowed)
            throw UsageError("spline: " + opt->get_name() + " applies to --kind " + kinds + " only");
    };
    only(o.o_degree, knotted, "bspline or nurbs");
    only(o.o_knots, knotted, "bspline or nurbs");
    only(o.o_knot_type, knotted, "bspline or nurbs");
    only(o.o_basis_at, knotted, "bspline or nurbs");
    only(o.o_basis, knotted, "bspline or nurbs");
    only(o.o_weights, o.kind == "nurbs", "nurbs");
    only(o.o_tangents, o.kind == "hermite", "hermite");
    only(o.o_tension, o.kind == "cardinal" || o.kind == "kb", "cardinal or kb");
    only(o.o_continuity, o.kind == "kb", "kb");
    only(o.o_bias, o.kind == "kb", "kb");
    only(o.o_ends, o.kind == "cardinal" || o.kind == "catmull-rom" || o.kind == "kb", "cardinal, catmull-rom or kb");
    only(o.o_param, o.kind == "natural", "natural");
    if (o.o_knots->count() && o.o_knot_type->count()) throw UsageError("spline: give --knots or --knot-type, not both");
}

// One source of points, one action, and options that go with them.
void check_spline_usage(const SplineOptions& o) {
    const int sources = static_cast<int>(o.o_points->count() > 0) + static_cast<int>(o.o_file->count() > 0);
    if (sources != 1) throw UsageError("spline: give exactly one of --points or --points-file");
    const bool pictures = o.o_render->count() > 0 || o.o_basis->count() > 0;
    const int actions = static_cast<int>(o.o_to_bezier->count() > 0) + static_cast<int>(o.o_eval->count() > 0) +
                        static_cast<int>(o.o_basis_at->count() > 0) + static_cast<int>(pictures);
    if (actions != 1)
        throw UsageError("spline: choose exactly one action: --to-bezier, --eval, --basis-at or --render/--basis");
    if (o.o_size->count() && !pictures) throw UsageError("spline: --size applies to --render and --basis only");
    if (o.o_derivative->count() && !o.o_eval->count()) throw UsageError("spline: --derivative needs --eval");
    check_kind_options(o);
}

void run_spline(const SplineOptions& o) {
    check_spline_usage(o);
    CurveFile file;
    if (o.o_points->count())
        file.points = parse_points_option("--points", o.points);
    else
        file = read_curve_file(o.points_file);
    const bool pictures = o.o_render->count() > 0 || o.o_basis->count() > 0;
    if (pictures && file.points.dimension == 3) throw UsageError("spline: --render and --basis draw 2-D curves only");
    if (file.points.dimension == 3)
        run<Point3>(o, file);
    else
        run<Point>(o, file);
}

// The spline's own options: knots and weights (B-splines, NURBS), tangents, tension, continuity,
// bias, ends (interpolating kinds), parametrisation (natural).
void add_shape_options(CLI::App* sub, SplineOptions& o) {
    o.o_degree =
        sub->add_option("--degree", o.degree, "bspline/nurbs degree, 1..64 (default 3)")->check(CLI::Range(1, 64));
    o.o_knots =
        sub->add_option("--knots", o.knots, "bspline/nurbs knot vector \"u0 u1 ...\" (count = points + degree + 1)");
    o.o_knot_type = sub->add_option("--knot-type", o.knot_type,
                                    "Without --knots: clamped (default, on [0, 1]), uniform or periodic")
                        ->check(CLI::IsMember({"clamped", "uniform", "periodic"}));
    o.o_weights = sub->add_option("--weights", o.weights, "nurbs weights \"w0 w1 ...\" (positive; default all 1)");
    o.o_tangents = sub->add_option("--tangents", o.tangents, "hermite tangents \"x,y x,y ...\", one per point");
    o.o_tension = sub->add_option("--tension", o.tension, "cardinal/kb tension (0 = Catmull-Rom, 1 = straight)");
    o.o_continuity = sub->add_option("--continuity", o.continuity, "kb continuity (-1 = box corners)");
    o.o_bias = sub->add_option("--bias", o.bias, "kb bias");
    o.o_ends = sub->add_option("--ends", o.ends, "cardinal/catmull-rom/kb ends: duplicate (default), closed or inner")
                   ->check(CLI::IsMember({"duplicate", "closed", "inner"}));
    o.o_param =
        sub->add_option("--param", o.param, "natural spline parametrisation: uniform (default), chord or centripetal")
            ->check(CLI::IsMember({"uniform", "chord", "centripetal"}));
}

// The actions: pieces, a point or derivative, basis functions, pictures.
void add_action_options(CLI::App* sub, SplineOptions& o) {
    o.o_to_bezier = sub->add_flag("--to-bezier")->description("Print the Bezier pieces");
    o.o_eval = sub->add_option("--eval", o.eval, "Print the point at T (or the K-th derivative with --derivative K)");
    o.o_derivative =
        sub->add_option("--derivative", o.derivative, "Derivative order K for --eval")->check(CLI::NonNegativeNumber);
    o.o_basis_at =
        sub->add_option("--basis-at", o.basis_at, "bspline/nurbs: print the basis functions N_i(T), one per line");
    o.o_render = sub->add_option("--render", o.render,
                                 "Draw the curve, its control polygon (dashed) and its knots (orange) into a PNG file");
    o.o_basis = sub->add_option("--basis", o.basis,
                                "bspline/nurbs: plot the basis functions N_i(t) over the domain into a PNG file");
    o.o_size = sub->add_option("--size", o.size, "With --render/--basis: canvas WxH in pixels (default 400x400)");
}

}  // namespace

void register_spline(CLI::App& app) {
    auto o = std::make_shared<SplineOptions>();
    CLI::App* sub = app.add_subcommand(
        "spline",
        "B-splines, NURBS and interpolating splines: print their Bezier pieces or evaluate them.\n"
        "Pieces print one after another separated by an empty line ('x y', NURBS 'x y w'). --eval uses the knot\n"
        "domain for bspline/nurbs and T in [0, pieces] for the interpolating kinds. Exit status 1: bad data; 2: bad "
        "usage.");
    sub->add_option("--kind", o->kind,
                    "bspline, nurbs, hermite, cardinal, catmull-rom, kb (Kochanek-Bartels) or natural")
        ->required()
        ->check(CLI::IsMember({"bspline", "nurbs", "hermite", "cardinal", "catmull-rom", "kb", "natural"}));
    o->o_points = sub->add_option("--points", o->points,
                                  "Points \"x,y x,y ...\" (or x,y,z): control points or points to pass through");
    o->o_file = sub->add_option(
        "--points-file", o->points_file,
        "JSON file {\"points\": [[x, y], ...], optional \"knots\", \"weights\", \"tangents\", \"degree\"}");
    add_shape_options(sub, *o);
    add_action_options(sub, *o);
    sub->callback([o] { run_spline(*o); });
}

}  // namespace casteljau::cli
