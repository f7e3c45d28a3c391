// bench/tolerance_study.cpp: what the flattening tolerance costs and buys, on the glyph set.
//
// For each pixel size and each tolerance, casteljau renders every glyph of the benchmark set
// (glyph_set.hpp) with Rasterizer::fill (exact overlaps on) into a reused buffer, exactly as
// compare_glyphs times it, and compares it pixel by pixel with casteljau's own render at the
// reference tolerance 0.001 px (a polygon within 0.001 px of the true curves: its exact-area
// coverage differs from the curves' by far less than 1/255). Reported per size and tolerance:
// throughput (thread CPU time, best of --runs rounds, round-robin over the tolerances), edges per glyph after
// flattening, and the error against the reference in 1/255: mean over all box pixels, mean over
// edge pixels (reference strictly between 0 and 255), max, and the share of pixels off by more
// than 1. The accuracy bounds for curved shapes are mean <= 0.5/255 and max <= 8/255.
// Next to the edges, "curvature-placed": the edges a flattener would need if it set every piece's
// length by the curve's local curvature, so that each piece's error (a balanced piece's, as the
// rasterizer flattens: 2/3 of its chord's sagitta, kappa l^2 / 12) equals the tolerance: per curve
// ceil(integral of sqrt(kappa / (12 tol)) ds), lines and closing lines one each. To first order in
// the pieces' length it is the floor of any flattening into balanced pieces at this tolerance,
// non-uniform ones included (Levien's method, which kurbo and vello use), against the equal pieces
// casteljau cuts, whose count follows the curve's largest second derivative.
//
// Usage: tolerance_study [--quick] [--runs R] [--min-time S] [--sizes 12,24,...]
//                        [--tolerances 0.01,0.025,...]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <numbers>
#include <string>
#include <vector>

#include "casteljau/raster.hpp"
#include "glyph_set.hpp"
#include "timer.hpp"

namespace {

constexpr double kReferenceTolerance = 0.001;
constexpr double kAcceptMean = 0.5, kAcceptMax = 8;

struct Options : bench::CommonOptions {
    std::vector<double> tolerances{0.01, 0.015, 0.025, 0.05, 0.1, 0.2, 0.25};
    std::string font = CASTELJAU_BENCH_FONT;
};

[[noreturn]] void usage(const char* msg) {
    std::fprintf(stderr,
                 "tolerance_study: %s\nusage: tolerance_study [--quick] [--runs R] [--min-time S] [--sizes 12,24,...]\n"
                 "                       [--tolerances 0.01,0.025,...] [--font FILE]\n",
                 msg);
    std::exit(2);
}

std::vector<double> split_numbers(const std::string& s) {
    std::vector<double> v;
    for (std::size_t p = 0; p < s.size();) {
        const std::size_t q = s.find(',', p);
        const double x = std::atof(s.substr(p, q - p).c_str());
        if (!(x > 0)) usage("list values must be positive numbers");
        v.push_back(x);
        p = q == std::string::npos ? s.size() : q + 1;
    }
    return v;
}

Options parse(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (o.parse_common(argc, argv, i, usage)) continue;
        if (a == "--tolerances") {
            if (i + 1 >= argc) usage("missing value after --tolerances");
            o.tolerances = split_numbers(argv[++i]);
        } else if (a == "--font") {
            if (i + 1 >= argc) usage("missing value after --font");
            o.font = argv[++i];
        } else if (a == "--help" || a == "-h") {
            usage("flattening tolerance study");
        } else {
            usage(("unknown argument " + a).c_str());
        }
    }
    return o;
}

// Renders glyph i of `set` at tolerance `tol` into `buf` (box-sized, row stride = box width).
struct Renderer {
    casteljau::Rasterizer rast;
    bench::BufferSink sink;
    void render(const bench::Glyph& g, double tol, std::uint8_t* buf) {
        std::memset(buf, 0, g.box.pixels());
        sink.buf = buf;
        sink.stride = g.box.width;
        casteljau::FillOptions o;
        o.tolerance = tol;
        rast.fill(g.path, g.to_box, o, casteljau::IRect{0, 0, g.box.width, g.box.height}, sink);
    }
};

// sqrt(|B' x B''| / |B'|) at t: sqrt(kappa) ds / dt, for a curve with derivative d1 and second
// derivative d2 there.
double sqrt_curvature_speed(casteljau::Point d1, casteljau::Point d2) {
    const double speed = std::sqrt(d1.x * d1.x + d1.y * d1.y);
    return speed > 0 ? std::sqrt(std::abs(d1.x * d2.y - d1.y * d2.x) / speed) : 0;
}

// The pieces a curve needs at tolerance `tol` when placed by curvature (see the top of the file):
// the integral by the midpoint rule over 64 steps, for a curve given its derivatives at t.
template <class Derivatives>
double curvature_pieces(double tol, Derivatives&& at) {
    constexpr int kSteps = 64;
    double sum = 0;
    for (int i = 0; i < kSteps; ++i) {
        casteljau::Point d1, d2;
        at((i + 0.5) / kSteps, d1, d2);
        sum += sqrt_curvature_speed(d1, d2);
    }
    return std::max(1.0, std::ceil(sum / kSteps / std::sqrt(12 * tol)));
}

// Edges of `path` under `m` with curvature-placed pieces at tolerance `tol` (conics as quadratics
// of their control points: fonts have none).
double curvature_placed_edges(const casteljau::Path& path, const casteljau::Affine& m, double tol) {
    using casteljau::Point;
    const auto pts = path.points();
    std::size_t k = 0;
    Point start{}, last{};
    double edges = 0;
    for (casteljau::Verb v : path.verbs()) {
        switch (v) {
            case casteljau::Verb::Move: start = last = m(pts[k++]); break;
            case casteljau::Verb::Line:
                last = m(pts[k++]);
                edges += 1;
                break;
            case casteljau::Verb::Quad:
            case casteljau::Verb::Conic: {
                const Point p0 = last, p1 = m(pts[k]), p2 = m(pts[k + 1]);
                k += 2;
                edges += curvature_pieces(tol, [&](double t, Point& d1, Point& d2) {
                    d1 = (p1 - p0) * (2 * (1 - t)) + (p2 - p1) * (2 * t);
                    d2 = (p0 - p1 * 2 + p2) * 2;
                });
                last = p2;
                break;
            }
            case casteljau::Verb::Cubic: {
                const Point p0 = last, p1 = m(pts[k]), p2 = m(pts[k + 1]), p3 = m(pts[k + 2]);
                k += 3;
                edges += curvature_pieces(tol, [&](double t, Point& d1, Point& d2) {
                    const double u = 1 - t;
                    d1 = (p1 - p0) * (3 * u * u) + (p2 - p1) * (6 * u * t) + (p3 - p2) * (3 * t * t);
                    d2 = (p0 - p1 * 2 + p2) * (6 * u) + (p1 - p2 * 2 + p3) * (6 * t);
                });
                last = p3;
                break;
            }
            case casteljau::Verb::Close:
                if (!(last == start)) edges += 1;
                last = start;
                break;
        }
    }
    return edges;
}

// The count checked against a shape whose integral is known: a circle of radius R has curvature
// 1 / R along 2 pi R, so 2 pi sqrt(R / (12 tol)) pieces, a quarter on each of its four cubics
// (which differ from the circle by 3e-4 R), each rounded up.
bool curvature_count_holds() {
    constexpr double kR = 100, kTol = 0.015;
    casteljau::Path circle;
    circle.add_circle({0, 0}, kR);
    const double quarter = 0.5 * std::numbers::pi * std::sqrt(kR / (12 * kTol));
    const double got = curvature_placed_edges(circle, casteljau::Affine{}, kTol);
    return std::abs(got - 4 * std::ceil(quarter)) <= 4;
}

struct Row {
    double glyphs_per_s = 0;
    std::size_t glyphs = 0;
    double edges = 0;
    double placed_edges = 0;  // curvature-placed
    double sum = 0, sum_edge = 0;
    std::size_t pixels = 0, edge_pixels = 0, over1 = 0;
    int max = 0;
    double mean() const { return pixels ? sum / static_cast<double>(pixels) : 0; }
    double mean_edge() const { return edge_pixels ? sum_edge / static_cast<double>(edge_pixels) : 0; }
};

std::string fmt_tol(double t) {
    char b[32];
    std::snprintf(b, sizeof b, "%.3g", t);
    return b;
}

}  // namespace

int main(int argc, char** argv) {
    const Options opt = parse(argc, argv);
    try {
        if (!curvature_count_holds()) {
            std::fprintf(stderr, "tolerance_study: error: the curvature-placed count of a circle is off\n");
            return 1;
        }
        bench::Font font(opt.font);
        Renderer ren;
        std::printf("tolerance_study: %s, %zu codepoints, unhinted; reference: casteljau at %.3g px\n",
                    font.path().c_str(), bench::benchmark_codepoints().size(), kReferenceTolerance);
        std::printf(
            "timing (thread CPU time): best of %d round(s), each >= %.2f s of whole passes over the set "
            "(Rasterizer::fill, "
            "exact overlaps on)\n\n",
            opt.runs, opt.quick ? 0.0 : opt.min_time);
        std::vector<std::vector<Row>> rows(opt.sizes.size(), std::vector<Row>(opt.tolerances.size()));
        unsigned checksum = 0;
        for (std::size_t si = 0; si < opt.sizes.size(); ++si) {
            const bench::GlyphSet set(font, opt.sizes[si]);
            const auto& gs = set.glyphs();
            const std::size_t n = gs.size();
            // Reference renders.
            std::vector<std::vector<std::uint8_t>> ref(n);
            for (std::size_t i = 0; i < n; ++i) {
                ref[i].resize(gs[i].box.pixels());
                ren.render(gs[i], kReferenceTolerance, ref[i].data());
            }
            std::vector<std::uint8_t> buf(set.max_box_pixels());
            // Accuracy and edge counts.
            for (std::size_t ti = 0; ti < opt.tolerances.size(); ++ti) {
                Row& row = rows[si][ti];
                for (std::size_t i = 0; i < n; ++i) {
                    ren.render(gs[i], opt.tolerances[ti], buf.data());
                    row.edges += static_cast<double>(ren.rast.last_stats().segments);
                    row.placed_edges += curvature_placed_edges(gs[i].path, gs[i].to_box, opt.tolerances[ti]);
                    for (std::size_t p = 0; p < gs[i].box.pixels(); ++p) {
                        const int r = ref[i][p];
                        const int d = std::abs(static_cast<int>(buf[p]) - r);
                        row.sum += d;
                        row.max = std::max(row.max, d);
                        if (d > 1) ++row.over1;
                        if (r != 0 && r != 255) {
                            row.sum_edge += d;
                            ++row.edge_pixels;
                        }
                    }
                    row.pixels += gs[i].box.pixels();
                }
                row.edges /= static_cast<double>(n);
                row.placed_edges /= static_cast<double>(n);
            }
            // Timing: calibrate, then round-robin rounds.
            auto pass = [&](double tol, int passes) {
                const double t0 = bench::thread_cpu_seconds();
                for (int p = 0; p < passes; ++p)
                    for (std::size_t i = 0; i < n; ++i) {
                        ren.render(gs[i], tol, buf.data());
                        checksum += buf[0];
                    }
                return bench::thread_cpu_seconds() - t0;
            };
            std::vector<int> passes(opt.tolerances.size(), 1);
            if (!opt.quick)
                for (std::size_t ti = 0; ti < opt.tolerances.size(); ++ti)
                    passes[ti] = std::max(
                        1, static_cast<int>(std::ceil(opt.min_time / std::max(1e-9, pass(opt.tolerances[ti], 1)))));
            std::vector<double> best(opt.tolerances.size(), INFINITY);
            for (int run = 0; run < opt.runs; ++run)
                for (std::size_t ti = 0; ti < opt.tolerances.size(); ++ti)
                    best[ti] = std::min(best[ti], pass(opt.tolerances[ti], passes[ti]));
            for (std::size_t ti = 0; ti < opt.tolerances.size(); ++ti) {
                rows[si][ti].glyphs_per_s = static_cast<double>(n) * passes[ti] / best[ti];
                rows[si][ti].glyphs = n;
            }
            std::fprintf(stderr, "  %d px done\n", opt.sizes[si]);
        }

        // Per size.
        // Relative speeds are against the default tolerance (or the closest one in the list).
        std::size_t base = 0;
        for (std::size_t ti = 0; ti < opt.tolerances.size(); ++ti)
            if (std::abs(opt.tolerances[ti] - casteljau::kDefaultTolerance) <
                std::abs(opt.tolerances[base] - casteljau::kDefaultTolerance))
                base = ti;
        std::printf("Per size (error vs the %.3g px reference, in 1/255; speed relative to %.3g px):\n\n",
                    kReferenceTolerance, opt.tolerances[base]);
        std::printf(
            "| px | tolerance | k glyphs/s | speed | edges/glyph | curvature-placed | mean err | mean err (edge px) | "
            "max err | px off > 1 |\n");
        std::printf("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
        for (std::size_t si = 0; si < opt.sizes.size(); ++si) {
            for (std::size_t ti = 0; ti < opt.tolerances.size(); ++ti) {
                const Row& r = rows[si][ti];
                std::printf("| %d | %.3g | %.1f | %.2f | %.1f | %.1f | %.4f | %.3f | %d | %.3f%% |\n", opt.sizes[si],
                            opt.tolerances[ti], r.glyphs_per_s / 1000, r.glyphs_per_s / rows[si][base].glyphs_per_s,
                            r.edges, r.placed_edges, r.mean(), r.mean_edge(), r.max,
                            100.0 * static_cast<double>(r.over1) / static_cast<double>(r.pixels));
            }
        }
        // Summary over sizes: worst errors, and the time to render the whole set once at every size.
        std::printf("\nSummary over all sizes (worst error; time to render the set once at every size):\n\n");
        std::printf(
            "| tolerance | worst mean err | worst mean err (edge px) | worst max err | meets mean <= %.1f, max <= %.0f "
            "| ms per set, all sizes | speed |\n",
            kAcceptMean, kAcceptMax);
        std::printf("|---:|---:|---:|---:|:---:|---:|---:|\n");
        std::vector<double> ms(opt.tolerances.size(), 0);
        for (std::size_t ti = 0; ti < opt.tolerances.size(); ++ti)
            for (std::size_t si = 0; si < opt.sizes.size(); ++si)
                ms[ti] += 1000.0 * static_cast<double>(rows[si][ti].glyphs) / rows[si][ti].glyphs_per_s;
        std::vector<std::string> misses;
        for (std::size_t ti = 0; ti < opt.tolerances.size(); ++ti) {
            double wm = 0, wme = 0;
            int wx = 0;
            for (std::size_t si = 0; si < opt.sizes.size(); ++si) {
                wm = std::max(wm, rows[si][ti].mean());
                wme = std::max(wme, rows[si][ti].mean_edge());
                wx = std::max(wx, rows[si][ti].max);
            }
            const bool meets = wm <= kAcceptMean && wx <= kAcceptMax;
            if (std::abs(opt.tolerances[ti] - casteljau::kDefaultTolerance) < 1e-12 && !meets)
                misses.push_back(fmt_tol(opt.tolerances[ti]));
            std::printf("| %.3g | %.4f | %.3f | %d | %s | %.2f | %.2f |\n", opt.tolerances[ti], wm, wme, wx,
                        meets ? "yes" : "no", ms[ti], ms[base] / ms[ti]);
        }
        std::printf("\n(checksum %u)\n", checksum);
        // A finding to report, not a failure of this program (it is a measurement tool).
        for (const std::string& t : misses)
            std::printf(
                "NOTE: the default tolerance %s px misses the bounds mean <= %.1f/255, max <= %.0f/255 on glyphs\n",
                t.c_str(), kAcceptMean, kAcceptMax);
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "tolerance_study: error: %s\n", e.what());
        return 1;
    }
}
