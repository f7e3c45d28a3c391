// bench/map_bench: filling a world map, casteljau side by side with AGG and Cairo in one process.
//
// Usage: map_bench FILE [--width 4096] [--rounds 5] [--layer NAME]
//                  [--profile render_map|cached|agg|both|both-cached|analysis]
//   (FILE: GeoJSON or TopoJSON; bench/setup_map_data.sh installs world-atlas 10m from npm.)
//   --profile runs one case alone, render_map's fill (with a MapCache kept across the rounds:
//   "cached"), AGG's, or the overlap analysis of every feature ("analysis": find_overlap_region,
//   which a MapCache runs once per feature), for a profiler; "both" ("both-cached") times
//   render_map (with a MapCache) and AGG in turn in one process.
// The map is read and projected (equirectangular, --bbox -180,-90,180,90 onto width x width/2)
// once, outside the timed region, into pixel-space polygons per feature (antimeridian split with
// casteljau's public split_ring_at_antimeridian). Timed, per round (thread CPU time, best of
// --rounds; see timer.hpp):
//   fill:         every feature filled in file order, nonzero, opaque black on a cleared image:
//                 casteljau separate (Canvas::fill_path, source-over; with the topology of each
//                 feature classified in the timed loop, so simple features are accumulated
//                 plainly; and with FillOptions::exact_overlaps off, plain accumulation), casteljau seamless
//                 (SeamlessCompositor, conflation-free), AGG (rasterizer_scanline_aa + scanline_p8,
//                 rgba8 pre), Cairo (image surface ARGB32, cairo_fill, antialias default).
//   fill+stroke:  the same plus a 0.8 px stroke of every ring with round joins: casteljau as the
//                 map command does it (all outlines in one nonzero path: shared borders drawn once),
//                 AGG conv_stroke per feature, Cairo cairo_stroke per feature.
//   render_map:   casteljau's whole map stage from MapData (projection + paths + seamless + strokes),
//                 into a new Pixmap and into one kept across the rounds (cleared by each render);
//                 with a MapCache, the first render of a new cache and the renders with one kept;
//                 the overlap analysis alone (find_overlap_region of every feature in pixels);
//                 and the fill against AGG's in alternating rounds (twice as many), which a
//                 machine whose speed drifts biases less than rounds timed in separate blocks.
//   threads:      render_map fill on 1 and 2 threads, wall time, into a new and into a kept Pixmap.
// Prints peak RSS at the end. Exits 1 when the fills with a topology verdict differ from the
// exact cells, or the borders stroked once from the union of every ring's stroke, by more than
// 1/255 at a pixel, or render_map's pixels with a MapCache from those without.
#include <agg_conv_stroke.h>
#include <agg_path_storage.h>
#include <agg_pixfmt_rgba.h>
#include <agg_rasterizer_scanline_aa.h>
#include <agg_renderer_base.h>
#include <agg_renderer_scanline.h>
#include <agg_rendering_buffer.h>
#include <agg_scanline_p.h>
#include <cairo.h>
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "casteljau/canvas.hpp"
#include "casteljau/geojson.hpp"
#include "casteljau/map.hpp"
#include "casteljau/file_io.hpp"
#include "casteljau/seamless.hpp"
#include "casteljau/stroke.hpp"
#include "timer.hpp"

using namespace casteljau;

namespace {

using Rings = std::vector<std::vector<Point>>;

double best_of(int rounds, const std::function<void()>& f) {
    double best = 1e300;
    for (int r = 0; r < rounds; ++r) {
        const double t0 = bench::thread_cpu_seconds();
        f();
        best = std::min(best, bench::thread_cpu_seconds() - t0);
    }
    return best;
}

}  // namespace

// render_map's style and options for the timed cases: a grey fill, the whole world, one thread
// (thread CPU time counts the calling thread only).
MapStyle grey_fill() {
    MapStyle style;
    style.layers[0].fill = Color::rgba(200, 200, 200);
    return style;
}

MapOptions world_options(int w, int h) {
    MapOptions mo;
    mo.width = w;
    mo.height = h;
    mo.bbox = Rect{-180, -90, 180, 90};
    mo.threads = 1;
    return mo;
}

// AGG 2.6 drawing the features: every ring of a feature in one path, nonzero, into one RGBA
// buffer that each render clears first.
class AggMap {
public:
    AggMap(const std::vector<Rings>& features, int w, int h)
        : buf_(static_cast<std::size_t>(w) * h * 4),
          rb_(buf_.data(), w, h, w * 4),
          pf_(rb_),
          ren_(pf_),
          paths_(features.size()) {
        for (std::size_t i = 0; i < features.size(); ++i)
            for (const auto& r : features[i]) {
                paths_[i].move_to(r[0].x, r[0].y);
                for (std::size_t k = 1; k < r.size(); ++k) paths_[i].line_to(r[k].x, r[k].y);
                paths_[i].close_polygon();
            }
    }
    // Every feature filled opaque black.
    void fill() {
        ren_.clear(agg::rgba8(0, 0, 0, 0));
        for (auto& p : paths_) draw(p, agg::rgba8(0, 0, 0, 255));
    }
    // Every feature filled grey, then every ring stroked 0.8 px wide with round joins and caps.
    void fill_stroke() {
        ren_.clear(agg::rgba8(0, 0, 0, 0));
        for (auto& p : paths_) draw(p, agg::rgba8(200, 200, 200, 255));
        for (auto& p : paths_) {
            agg::conv_stroke<agg::path_storage> st(p);
            st.width(0.8);
            st.line_join(agg::round_join);
            st.line_cap(agg::round_cap);
            draw(st, agg::rgba8(0, 0, 0, 255));
        }
    }

private:
    template <class Source>
    void draw(Source& src, agg::rgba8 color) {
        ras_.reset();
        ras_.filling_rule(agg::fill_non_zero);
        ras_.add_path(src);
        agg::render_scanlines_aa_solid(ras_, sl_, ren_, color);
    }

    std::vector<std::uint8_t> buf_;
    agg::rendering_buffer rb_;
    agg::pixfmt_rgba32_pre pf_;
    agg::renderer_base<agg::pixfmt_rgba32_pre> ren_;
    agg::rasterizer_scanline_aa<> ras_;
    agg::scanline_p8 sl_;
    std::vector<agg::path_storage> paths_;
};

// --profile: one case alone, for a profiler (bench/stage_profile.py): render_map's fill or AGG's;
// "both" times the two in turn, round by round, so that their times come from one process.
int run_profile(const std::string& name, const MapData& data, const std::vector<Rings>& features, int w, int h,
                int rounds) {
    const MapStyle style = grey_fill();
    MapOptions mo = world_options(w, h);
    const bool agg = name == "agg" || name == "both" || name == "both-cached", ours = name != "agg";
    MapCache cache;
    if (name == "cached" || name == "both-cached") mo.cache = &cache;
    std::optional<AggMap> agg_map;
    if (agg) agg_map.emplace(features, w, h);
    double best_ours = 1e300, best_agg = 1e300;
    for (int r = 0; r < rounds; ++r) {
        if (ours)
            best_ours = std::min(best_ours, best_of(1, [&] { (void)render_map(data, MapProjection{}, style, mo); }));
        if (agg) best_agg = std::min(best_agg, best_of(1, [&] { agg_map->fill(); }));
    }
    if (ours) std::printf("profile render_map fill: best of %d rounds %.2f ms\n", rounds, best_ours * 1e3);
    if (agg) std::printf("profile agg fill: best of %d rounds %.2f ms\n", rounds, best_agg * 1e3);
    return 0;
}

int run(int argc, char** argv);

int main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "map_bench: error: %s\n", e.what());
        return 1;
    }
}

int run(int argc, char** argv) {
    auto usage = [] {
        std::fprintf(stderr,
                     "usage: map_bench FILE [--width 4096] [--rounds 5] [--layer NAME] [--profile "
                     "render_map|cached|agg|both|both-cached|analysis]\n");
        return 2;
    };
    if (argc < 2 || argv[1][0] == '-') return usage();
    int W = 4096, rounds = 5;
    std::string layer, profile;
    for (int i = 2; i < argc; i += 2) {
        if (i + 1 >= argc) return usage();
        if (!std::strcmp(argv[i], "--width"))
            W = std::atoi(argv[i + 1]);
        else if (!std::strcmp(argv[i], "--rounds"))
            rounds = std::atoi(argv[i + 1]);
        else if (!std::strcmp(argv[i], "--layer"))
            layer = argv[i + 1];
        else if (!std::strcmp(argv[i], "--profile"))
            profile = argv[i + 1];
        else
            return usage();
    }
    if (W < 2 || rounds < 1 ||
        !(profile.empty() || profile == "render_map" || profile == "cached" || profile == "agg" || profile == "both" ||
          profile == "both-cached" || profile == "analysis"))
        return usage();
    const int H = W / 2;
    const auto bytes = read_file(argv[1]);
    const MapData data =
        read_map_data(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), layer);
    // Pixel-space polygons per feature.
    std::vector<Rings> features;
    std::size_t vertices = 0;
    for (const Feature& f : data.features) {
        Rings rings;
        for (const Geometry& g : f.geometries) {
            if (g.kind != GeometryKind::Polygons) continue;
            std::size_t start = 0;
            for (std::uint32_t end : g.ring_ends) {
                Rings pieces;
                split_ring_at_antimeridian(std::span<const Point>(g.points).subspan(start, end - start), pieces);
                for (auto& p : pieces) {
                    for (Point& q : p) q = {(q.x + 180.0) / 360.0 * W, (90.0 - q.y) / 180.0 * H};
                    vertices += p.size();
                    rings.push_back(std::move(p));
                }
                start = end;
            }
        }
        features.push_back(std::move(rings));
    }
    std::vector<Path> paths;
    for (const Rings& rs : features) {
        Path p;
        for (const auto& r : rs) p.add_polygon(r, true);
        paths.push_back(std::move(p));
    }
    std::printf("map_bench: %s, %zu features, %zu vertices, %d x %d, best of %d rounds (thread CPU time)\n", argv[1],
                features.size(), vertices, W, H, rounds);

    // The overlap analysis of every feature's rings in pixels: what a MapCache's first render adds
    // (it analyses render_map's own paths of the same rings). The count of boxes found must be the
    // same in every round.
    std::size_t analysis_boxes = 0;
    auto analyse = [&] {
        std::size_t n = 0;
        for (const Path& p : paths) n += find_overlap_region(p).boxes.size();
        if (analysis_boxes != 0 && n != analysis_boxes) std::abort();
        analysis_boxes = n;
    };
    if (profile == "analysis") {
        const double t = best_of(rounds, analyse);
        std::printf("profile find_overlap_region: best of %d rounds %.2f ms, %zu boxes\n", rounds, t * 1e3,
                    analysis_boxes);
        return 0;
    }
    if (!profile.empty()) return run_profile(profile, data, features, W, H, rounds);

    Pixmap pm(W, H);
    const double t_sep = best_of(rounds, [&] {
        pm.fill(Color::transparent());
        Canvas c(pm);
        for (const Path& p : paths) c.fill_path(p, Paint::solid(Color::black()));
    });
    // The topology verdict decided per feature inside the timed loop (classify_topology, then the
    // plain accumulation for features proven simple), and its agreement with the exact cells.
    std::vector<std::uint8_t> exact_alpha(static_cast<std::size_t>(W) * H);
    for (std::size_t i = 0; i < exact_alpha.size(); ++i) exact_alpha[i] = pm.data()[4 * i + 3];
    std::size_t simple = 0;
    const double t_sep_verdict = best_of(rounds, [&] {
        pm.fill(Color::transparent());
        Canvas c(pm);
        simple = 0;
        for (const Path& p : paths) {
            c.fill_options().topology = classify_topology(p);
            simple += c.fill_options().topology == Topology::Simple;
            c.fill_path(p, Paint::solid(Color::black()));
        }
    });
    const double t_classify = best_of(rounds, [&] {
        std::size_t n = 0;
        for (const Path& p : paths) n += classify_topology(p) == Topology::Simple;
        if (n != simple) std::abort();
    });
    int verdict_max_diff = 0;
    for (std::size_t i = 0; i < exact_alpha.size(); ++i)
        verdict_max_diff = std::max(verdict_max_diff, std::abs(int(pm.data()[4 * i + 3]) - int(exact_alpha[i])));
    const double t_sep_plain = best_of(rounds, [&] {
        pm.fill(Color::transparent());
        Canvas c(pm);
        c.fill_options().exact_overlaps = false;
        for (const Path& p : paths) c.fill_path(p, Paint::solid(Color::black()));
    });
    SeamlessCompositor ac(W, H);
    Rasterizer raster;
    // Every feature's fill in `color`, composited seamlessly (last feature first) onto a cleared pm.
    auto seamless_fill = [&](Color color) {
        pm.fill(Color::transparent());
        ac.clear();
        for (std::size_t i = paths.size(); i-- > 0;) ac.add(raster, paths[i], FillOptions{}, color);
        ac.composite_onto(pm);
    };
    const double t_seam = best_of(rounds, [&] { seamless_fill(Color::black()); });
    StrokeStyle ss;
    ss.width = 0.8;
    ss.join = LineJoin::Round;
    ss.cap = LineCap::Round;
    const double t_seam_stroke = best_of(rounds, [&] {
        seamless_fill(Color::rgba(200, 200, 200));
        Path outline;
        for (const Path& p : paths) outline.append(stroke(p, ss));
        Canvas c(pm);
        c.fill_path(outline, Paint::solid(Color::black()));
    });
    // The same with every shared border stroked once (SharedBorders, as render_map does).
    StrokeStyle chain_style = ss;
    chain_style.cap = LineCap::Butt;
    const Pixmap pm_union = pm;  // the union of every ring's stroke, from the row above
    const double t_seam_stroke_once = best_of(rounds, [&] {
        seamless_fill(Color::rgba(200, 200, 200));
        SharedBorders borders;
        Path outline, chains, whole;
        for (const Path& p : paths) {
            chains.clear();
            whole.clear();
            borders.add(p, chains, whole, stroke_merge_distance());
            outline.append(stroke(chains, chain_style));
            outline.append(stroke(whole, ss));
        }
        Canvas c(pm);
        c.fill_path(outline, Paint::solid(Color::black()));
    });
    int once_max_diff = 0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x)
            once_max_diff = std::max(once_max_diff, std::abs(int(pm.pixel(x, y).a) - int(pm_union.pixel(x, y).a)));

    // AGG.
    AggMap agg_map(features, W, H);
    const double t_agg = best_of(rounds, [&] { agg_map.fill(); });
    const double t_agg_stroke = best_of(rounds, [&] { agg_map.fill_stroke(); });

    // Cairo.
    cairo_surface_t* surf = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, W, H);
    cairo_t* cr = cairo_create(surf);
    auto cairo_path = [&](const Rings& rs) {
        for (const auto& r : rs) {
            cairo_move_to(cr, r[0].x, r[0].y);
            for (std::size_t k = 1; k < r.size(); ++k) cairo_line_to(cr, r[k].x, r[k].y);
            cairo_close_path(cr);
        }
    };
    auto cairo_clear = [&] {
        cairo_set_operator(cr, CAIRO_OPERATOR_CLEAR);
        cairo_paint(cr);
        cairo_set_operator(cr, CAIRO_OPERATOR_OVER);
    };
    cairo_set_fill_rule(cr, CAIRO_FILL_RULE_WINDING);
    const double t_cairo = best_of(rounds, [&] {
        cairo_clear();
        cairo_set_source_rgb(cr, 0, 0, 0);
        for (const Rings& rs : features) {
            cairo_path(rs);
            cairo_fill(cr);
        }
        cairo_surface_flush(surf);
    });
    cairo_set_line_width(cr, 0.8);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
    const double t_cairo_stroke = best_of(rounds, [&] {
        cairo_clear();
        for (const Rings& rs : features) {
            cairo_path(rs);
            cairo_set_source_rgb(cr, 0.78, 0.78, 0.78);
            cairo_fill_preserve(cr);
            cairo_set_source_rgb(cr, 0, 0, 0);
            cairo_stroke(cr);
        }
        cairo_surface_flush(surf);
    });
    cairo_destroy(cr);
    cairo_surface_destroy(surf);

    // The whole map stage from MapData.
    MapStyle style = grey_fill();
    MapOptions mo = world_options(W, H);
    const MapProjection eq;
    const double t_map = best_of(rounds, [&] { (void)render_map(data, eq, style, mo); });
    // The same against AGG with the two alternating round by round, so that both see the machine
    // at the same speed (the rows above time each case's rounds in one block, seconds apart).
    double t_map_alt = 1e300, t_agg_alt = 1e300;
    for (int r = 0; r < 2 * rounds; ++r) {
        t_agg_alt = std::min(t_agg_alt, best_of(1, [&] { agg_map.fill(); }));
        t_map_alt = std::min(t_map_alt, best_of(1, [&] { (void)render_map(data, eq, style, mo); }));
    }
    // Threads: wall time (steady clock), best of the rounds, 1 and 2 threads alternating; into a
    // new Pixmap each time (its pages faulted in while drawing), then into one kept Pixmap.
    const MapFrame frame = fit_map(data, eq, mo);
    Pixmap reused(frame.width, frame.height);
    double wall[2][2] = {{1e30, 1e30}, {1e30, 1e30}};  // [kept][threads - 1]
    for (int kept : {0, 1})
        for (int r = 0; r < rounds; ++r)
            for (int t : {1, 2}) {
                mo.threads = t;
                const auto t0 = std::chrono::steady_clock::now();
                if (kept)
                    render_map(data, eq, frame, style, mo, reused);
                else
                    (void)render_map(data, eq, style, mo);
                const double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
                wall[kept][t - 1] = std::min(wall[kept][t - 1], sec);
            }
    mo.threads = 1;
    // With a MapCache: the first render of each fresh cache (which finds the analyses), and the
    // renders that follow with one kept across the rounds. The pixels must not move.
    double t_map_first = 1e300;
    for (int r = 0; r < rounds; ++r) {
        MapCache fresh;
        mo.cache = &fresh;
        t_map_first = std::min(t_map_first, best_of(1, [&] { (void)render_map(data, eq, style, mo); }));
    }
    MapCache cache;
    mo.cache = &cache;
    const Pixmap with_cache = render_map(data, eq, style, mo);
    const double t_map_cached = best_of(rounds, [&] { (void)render_map(data, eq, style, mo); });
    const double t_map_cached_reused = best_of(rounds, [&] { render_map(data, eq, frame, style, mo, reused); });
    const double t_analysis = best_of(rounds, analyse);
    mo.cache = nullptr;
    const Pixmap without_cache = render_map(data, eq, style, mo);
    // Both exact: a pixel the analysis proves plain where the per-cell check computed it again
    // may round to the neighbouring level.
    int cache_max_diff = 0;
    std::size_t cache_diff_pixels = 0;
    for (int y = 0; y < with_cache.height(); ++y)
        for (int x = 0; x < with_cache.width(); ++x) {
            const std::uint8_t* a = with_cache.data() + y * with_cache.stride() + 4 * x;
            const std::uint8_t* b = without_cache.data() + y * without_cache.stride() + 4 * x;
            int d = 0;
            for (int c = 0; c < 4; ++c) d = std::max(d, std::abs(int(a[c]) - int(b[c])));
            cache_max_diff = std::max(cache_max_diff, d);
            cache_diff_pixels += d > 0;
        }
    mo.exact_overlaps = false;
    const double t_map_plain = best_of(rounds, [&] { (void)render_map(data, eq, style, mo); });
    mo.exact_overlaps = true;
    // Into one Pixmap kept across the rounds, as AGG and Cairo draw into one buffer above (each
    // render clears it first, as AGG's and Cairo's rounds do).
    const double t_map_reused = best_of(rounds, [&] { render_map(data, eq, frame, style, mo, reused); });
    style.layers[0].stroke = Color::black();
    style.layers[0].stroke_width = 0.8;
    const double t_map_stroke = best_of(rounds, [&] { (void)render_map(data, eq, style, mo); });
    const double t_map_stroke_reused = best_of(rounds, [&] { render_map(data, eq, frame, style, mo, reused); });

    std::printf("%-44s %10s %10s\n", "case", "ms", "vs best peer");
    const double peer_fill = std::min(t_agg, t_cairo), peer_stroke = std::min(t_agg_stroke, t_cairo_stroke);
    auto row = [](const char* name, double t, double ref) {
        std::printf("%-44s %10.1f %10.2fx\n", name, t * 1e3, ref / t);
    };
    row("fill: casteljau separate (source-over)", t_sep, peer_fill);
    row("fill: casteljau separate, topology per feature", t_sep_verdict, peer_fill);
    row("  of which classify_topology alone", t_classify, peer_fill);
    row("fill: casteljau separate, exact_overlaps off", t_sep_plain, peer_fill);
    row("fill: casteljau seamless compositor", t_seam, peer_fill);
    row("fill: AGG 2.6", t_agg, peer_fill);
    row("fill: Cairo", t_cairo, peer_fill);
    row("fill+stroke: casteljau seamless + union stroke", t_seam_stroke, peer_stroke);
    row("fill+stroke: casteljau seamless + borders once", t_seam_stroke_once, peer_stroke);
    row("fill+stroke: AGG 2.6", t_agg_stroke, peer_stroke);
    row("fill+stroke: Cairo", t_cairo_stroke, peer_stroke);
    row("render_map fill (projection included)", t_map, peer_fill);
    row("render_map fill, into a kept Pixmap", t_map_reused, peer_fill);
    row("render_map fill, exact_overlaps off", t_map_plain, peer_fill);
    row("render_map fill, first render, new MapCache", t_map_first, peer_fill);
    row("render_map fill, MapCache kept", t_map_cached, peer_fill);
    row("render_map fill, MapCache kept, kept Pixmap", t_map_cached_reused, peer_fill);
    row("  find_overlap_region alone", t_analysis, peer_fill);
    row("render_map fill+stroke", t_map_stroke, peer_stroke);
    row("render_map fill+stroke, into a kept Pixmap", t_map_stroke_reused, peer_stroke);
    std::printf("render_map fill against AGG in alternating rounds: %.1f against %.1f ms (%.2fx)\n", t_map_alt * 1e3,
                t_agg_alt * 1e3, t_agg_alt / t_map_alt);
    for (int kept : {0, 1})
        std::printf("render_map fill%s, wall time: 1 thread %.1f ms, 2 threads %.1f ms (%.2fx)\n",
                    kept ? " into a kept Pixmap" : "", wall[kept][0] * 1e3, wall[kept][1] * 1e3,
                    wall[kept][0] / wall[kept][1]);
    std::printf(
        "topology per feature: %zu of %zu features simple; max |alpha difference| against the exact cells: %d/255\n",
        simple, paths.size(), verdict_max_diff);
    std::printf("borders once against the union of every ring's stroke: max |alpha difference| %d/255\n",
                once_max_diff);
    rusage ru{};
    getrusage(RUSAGE_SELF, &ru);
    std::printf("peak RSS: %.1f MB (input file %.1f MB)\n", ru.ru_maxrss / 1024.0, bytes.size() / 1e6);
    // Both comparisons are of exact renders of the same region: more than a rounding step apart
    // means one of them is broken, and its time is not worth reporting.
    std::printf("render_map fill with a MapCache against without: %zu pixels differ, max |difference| %d/255\n",
                cache_diff_pixels, cache_max_diff);
    if (verdict_max_diff > 1 || once_max_diff > 1 || cache_max_diff > 1) {
        std::fprintf(stderr, "map_bench: error: renders that must agree differ by more than 1/255\n");
        return 1;
    }
    return 0;
}
