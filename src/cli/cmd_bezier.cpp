// casteljau bezier: compute with one Bézier curve of any degree (2-D or 3-D) and print the result.
//
//   casteljau bezier --points "0,0 48,96 120,120 216,72" --eval 0.4        -> 69.12 80.64
//   casteljau bezier --points "0,0 0,100 100,0 100,100" --elevate          -> 5 lines "x y"
//   casteljau bezier --points-file curve.json --triangle 0.5               -> rows, blank line between
//   casteljau bezier --points "0,0 48,96 120,120 216,72" --render c.png --construction 0.4
//
// Output format: curve_args.hpp. Exit status 1 for bad data (too few points, degree above 64,
// unreadable or malformed file), 2 for bad usage (malformed option text, t outside [0, 1], no or
// several actions).
#include <algorithm>
#include <cmath>
#include <optional>
#include <iostream>
#include <memory>
#include <sstream>

#include "casteljau/bezier.hpp"
#include "casteljau/figures.hpp"
#include "casteljau/png.hpp"
#include "cli/cli.hpp"
#include "cli/curve_args.hpp"

namespace casteljau::cli {

namespace {

struct BezierOptions {
    std::string points, points_file;
    double eval = 0, split = 0, triangle = 0, curvature = 0;
    int derivative = 0, times = 1;
    std::string method = "combined", subcurve, render, size = "400x400";
    double construction = 0;
    CLI::Option *o_points = nullptr, *o_file = nullptr, *o_eval = nullptr, *o_derivative = nullptr,
                *o_elevate = nullptr, *o_times = nullptr, *o_reduce = nullptr, *o_method = nullptr, *o_split = nullptr,
                *o_subcurve = nullptr, *o_triangle = nullptr, *o_bounds = nullptr, *o_power = nullptr,
                *o_curvature = nullptr, *o_interpolate = nullptr, *o_render = nullptr, *o_size = nullptr,
                *o_construction = nullptr;
};

template <CurvePoint P>
void print_points(std::ostream& out, std::span<const P> pts, double scale) {
    for (const P& p : pts) out << format_point(to_p3(p), scale, point_dimension<P>) << '\n';
}

// --interpolate: the cubic through four points at t = 0, 1/3, 2/3 and 1.
template <CurvePoint P>
void print_interpolating_cubic(std::ostream& out, const PointList& input) {
    if (input.points.size() != 4)
        throw Error(ErrorKind::InvalidData,
                    "--interpolate needs exactly 4 points (Q0..Q3 at t = 0, 1/3, 2/3, 1), got " +
                        std::to_string(input.points.size()));
    const auto& q = input.points;
    const Bezier<P> c = interpolate_cubic(to_point<P>(q[0]), to_point<P>(q[1]), to_point<P>(q[2]), to_point<P>(q[3]));
    print_points<P>(out, c.points(), input.scale());
}

// --render: the curve's figure (2-D only), with the de Casteljau construction at --construction.
template <CurvePoint P>
void render_figure(const BezierOptions& o, const Bezier<P>& curve) {
    if constexpr (std::same_as<P, Point>) {
        FigureOptions fo;
        parse_size_option("--size", o.size, fo.width, fo.height);
        fo.margin = std::min(24.0, std::min(fo.width, fo.height) / 10.0);
        std::optional<double> t;
        if (o.o_construction->count()) t = o.construction;
        write_png(draw_bezier_figure(curve, fo, t).image, o.render);
    } else {
        (void)curve;
        throw UsageError("--render draws 2-D curves only (got 3-D points)");
    }
}

// --reduce: the curve of one degree less, its deviation on standard error.
template <CurvePoint P>
void print_reduced(std::ostream& out, const BezierOptions& o, const Bezier<P>& curve, double scale) {
    const ReductionMethod m = o.method == "forward"    ? ReductionMethod::Forward
                              : o.method == "backward" ? ReductionMethod::Backward
                                                       : ReductionMethod::Combined;
    const Reduction<P> r = reduce_degree(curve, m);
    print_points<P>(out, r.curve.points(), scale);
    std::cerr << "casteljau: max deviation " << format_number(r.max_deviation, 0) << " (sampled), bound "
              << format_number(r.deviation_bound, 0) << "\n";
}

// The one computation the options ask for, printed to `out`.
template <CurvePoint P>
void print_result(std::ostream& out, const BezierOptions& o, const Bezier<P>& curve, double scale) {
    auto print = [&](const P& p) { out << format_point(to_p3(p), scale, point_dimension<P>) << '\n'; };
    if (o.o_eval->count()) {
        print(o.o_derivative->count() ? curve.derivative(o.derivative, o.eval) : curve.eval(o.eval));
    } else if (o.o_derivative->count()) {
        print_points<P>(out, curve.derivative_points(o.derivative), scale);
    } else if (o.o_elevate->count()) {
        print_points<P>(out, curve.elevated(o.times).points(), scale);
    } else if (o.o_reduce->count()) {
        print_reduced(out, o, curve, scale);
    } else if (o.o_split->count()) {
        const auto [l, r] = curve.split(o.split);
        print_points<P>(out, l.points(), scale);
        out << '\n';
        print_points<P>(out, r.points(), scale);
    } else if (o.o_subcurve->count()) {
        const auto t = parse_numbers_option("--subcurve", o.subcurve);
        if (t.size() != 2) throw UsageError("--subcurve: expected two parameters 'T0,T1'");
        print_points<P>(out, curve.subcurve(t[0], t[1]).points(), scale);
    } else if (o.o_triangle->count()) {
        const auto rows = curve.triangle(o.triangle);
        for (std::size_t r = 0; r < rows.size(); ++r) {
            if (r) out << '\n';
            print_points<P>(out, rows[r], scale);
        }
    } else if (o.o_bounds->count()) {
        const Box<P> b = curve.bounds();
        print(b.lo);
        print(b.hi);
    } else if (o.o_power->count()) {
        print_points<P>(out, curve.to_power().coefficients, scale);
    } else if (o.o_curvature->count()) {
        double k = 0;
        if constexpr (std::same_as<P, Point>)
            k = curve.signed_curvature(o.curvature);
        else
            k = curve.curvature(o.curvature);
        out << (std::isinf(k) ? std::string("inf") : format_number(k, 0)) << '\n';
    }
}

template <CurvePoint P>
void run(const BezierOptions& o, const PointList& input) {
    std::ostringstream out;
    if (o.o_interpolate->count()) {
        print_interpolating_cubic<P>(out, input);
        std::cout << out.str();
        return;
    }
    std::vector<P> pts;
    for (const Point3& p : input.points) pts.push_back(to_point<P>(p));
    const Bezier<P> curve(std::move(pts));
    if (o.o_render->count()) return render_figure(o, curve);
    print_result(out, o, curve, input.scale());
    std::cout << out.str();
}

// One source of points, one action, and options that go with their action.
void check_bezier_usage(const BezierOptions& o) {
    const int sources = static_cast<int>(o.o_points->count() > 0) + static_cast<int>(o.o_file->count() > 0);
    if (sources != 1) throw UsageError("bezier: give exactly one of --points or --points-file");
    int actions = 0;
    for (CLI::Option* a : {o.o_eval, o.o_elevate, o.o_reduce, o.o_split, o.o_subcurve, o.o_triangle, o.o_bounds,
                           o.o_power, o.o_curvature, o.o_interpolate, o.o_render})
        actions += a->count() > 0;
    if (o.o_derivative->count() && !o.o_eval->count()) ++actions;
    if (actions != 1)
        throw UsageError(
            "bezier: choose exactly one action: --eval, --derivative, --elevate, --reduce, --split, "
            "--subcurve, --triangle, --bounds, --power, --curvature, --interpolate or --render");
    if ((o.o_size->count() || o.o_construction->count()) && !o.o_render->count())
        throw UsageError("bezier: --size and --construction apply to --render only");
    if (o.o_times->count() && !o.o_elevate->count()) throw UsageError("bezier: --times applies to --elevate only");
    if (o.o_method->count() && !o.o_reduce->count()) throw UsageError("bezier: --method applies to --reduce only");
}

void run_bezier(const BezierOptions& o) {
    check_bezier_usage(o);
    const PointList pts =
        o.o_points->count() ? parse_points_option("--points", o.points) : read_curve_file(o.points_file).points;
    if (pts.dimension == 3)
        run<Point3>(o, pts);
    else
        run<Point>(o, pts);
}

// The computations that print: evaluation, derivatives, elevation, reduction, splitting, the
// triangle, bounds, power form, curvature, interpolation.
void add_computation_options(CLI::App* sub, BezierOptions& o) {
    o.o_eval =
        sub->add_option("--eval", o.eval, "Print P(T) (de Casteljau), or the K-th derivative with --derivative K");
    o.o_derivative = sub->add_option("--derivative", o.derivative,
                                     "Derivative order K >= 0; alone, print the K-th derivative's control points")
                         ->check(CLI::NonNegativeNumber);
    o.o_elevate = sub->add_flag("--elevate")->description("Print the control points after exact degree elevation");
    o.o_times = sub->add_option("--times", o.times, "With --elevate: how many times (default 1)")
                    ->check(CLI::NonNegativeNumber);
    o.o_reduce = sub->add_flag("--reduce")->description("Print the degree n-1 approximation (deviation on stderr)");
    o.o_method = sub->add_option("--method", o.method, "With --reduce: forward, backward or combined (default)")
                     ->check(CLI::IsMember({"forward", "backward", "combined"}));
    o.o_split = sub->add_option("--split", o.split, "Print the two halves at T (left, empty line, right)");
    o.o_subcurve = sub->add_option("--subcurve", o.subcurve, "Print the sub-curve over [T0, T1], given as \"T0,T1\"");
    o.o_triangle = sub->add_option("--triangle", o.triangle, "Print the de Casteljau triangle at T, one row per block");
    o.o_bounds = sub->add_flag("--bounds")->description("Print the tight bounding box: min corner, then max corner");
    o.o_power =
        sub->add_flag("--power")->description("Print the power-form coefficients a_0..a_n of P(t) = sum a_k t^k");
    o.o_curvature =
        sub->add_option("--curvature", o.curvature, "Print the curvature at T (signed in 2-D; inf at a cusp)");
    o.o_interpolate =
        sub->add_flag("--interpolate")
            ->description("Treat 4 points as Q0..Q3 and print the cubic through them at t = 0, 1/3, 2/3, 1");
}

// The figure: --render with its size and the construction drawn.
void add_render_options(CLI::App* sub, BezierOptions& o) {
    o.o_render =
        sub->add_option("--render", o.render, "Draw the curve, its control polygon and points into a PNG file");
    o.o_size = sub->add_option("--size", o.size, "With --render: canvas WxH in pixels (default 400x400)");
    o.o_construction =
        sub->add_option("--construction", o.construction,
                        "With --render: draw the de Casteljau construction at T (levels coloured, P(T) red)");
}

}  // namespace

void register_bezier(CLI::App& app) {
    auto o = std::make_shared<BezierOptions>();
    CLI::App* sub = app.add_subcommand(
        "bezier",
        "Compute with a Bezier curve of any degree (2-D or 3-D): evaluate, differentiate, split, elevate, reduce.\n"
        "Exactly one action. Points print as 'x y' (or 'x y z') one per line; several curves or triangle rows are\n"
        "separated by an empty line. Numbers: 12 significant digits, rounding noise below 1e-12 x the input scale\n"
        "printed as 0. Exit status 1: bad data; 2: bad usage.");
    o->o_points =
        sub->add_option("--points", o->points, "Control points \"x,y x,y ...\" (or x,y,z); degree = count - 1 (1..64)");
    o->o_file =
        sub->add_option("--points-file", o->points_file, "JSON file {\"points\": [[x, y], ...]} ('-' reads stdin)");
    add_computation_options(sub, *o);
    add_render_options(sub, *o);
    sub->callback([o] { run_bezier(*o); });
}

}  // namespace casteljau::cli
