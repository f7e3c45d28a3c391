// bench/map_accuracy: how far the map stage's geometry simplification (MapOptions::simplify) moves
// coverage, against the exact rendering of the original geometry.
//
// Usage: map_accuracy FILE [--layer NAME] [--width W]... [--simplify E]... [--window T] [--stroke-width S]
//   The world (equirectangular, bbox -180,-90,180,90) onto W x W/2 pixels, as bench/mapnik_compare.py
//   draws it. For each width, two pictures: the fill (opaque black, seamless) and the stroke (no
//   fill, S px, round joins and caps), each as coverage (the alpha channel on a transparent image).
//   Reference: the original geometry (simplify 0) drawn window by window, T x T pixels each (default
//   64; 0: the whole image at once), every window drawing only the features whose bounds reach it,
//   so that no fill runs out of the rasterizer's exact-work budget (past it dense cells are
//   approximated, see casteljau/raster.hpp) and strokes go through their outlines
//   (MapOptions::sampled_strokes off) flattened within 0.001 px: the exact union.
//   Output: render_map of the whole image with simplify E, as `casteljau map` draws it (round
//   strokes sampled, casteljau/round_stroke.hpp).
// Prints per width, picture and E: mean and max of |output - reference| over all pixels, in 1/255 of
// coverage, and how many pixels differ; then the same for the simplified geometry drawn window by
// window like the reference (the simplification's own error, without what the whole-image fill
// approximates past its work budget or the sampled strokes' error). The reference's own check: the whole-image render of the
// original against it (E = 0).
#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <stdexcept>
#include <string>
#include <vector>

#include "casteljau/geojson.hpp"
#include "casteljau/map.hpp"
#include "casteljau/projection.hpp"

using namespace casteljau;

namespace {

struct Picture {
    const char* name;
    MapStyle style;
};

std::vector<Picture> pictures(double stroke_width) {
    MapStyle fill;
    fill.layers[0].fill = Color::black();
    MapStyle line;
    line.layers[0].fill.reset();
    line.layers[0].stroke = Color::black();
    line.layers[0].stroke_width = stroke_width;
    return {{"fill", fill}, {"stroke", line}};
}

std::vector<std::uint8_t> alpha_of(const Pixmap& pm) {
    std::vector<std::uint8_t> a(static_cast<std::size_t>(pm.width()) * static_cast<std::size_t>(pm.height()));
    for (int y = 0; y < pm.height(); ++y)
        for (int x = 0; x < pm.width(); ++x) a[static_cast<std::size_t>(y) * pm.width() + x] = pm.pixel(x, y).a;
    return a;
}

// The pixel bounds of each feature's positions under `frame` (the whole plane when a step crosses
// the antimeridian: the renderer's cut adds positions).
std::vector<Rect> feature_bounds(const MapData& data, const MapProjection& proj, const MapFrame& frame) {
    std::vector<Rect> out;
    for (const Feature& f : data.features) {
        Rect r{INFINITY, INFINITY, -INFINITY, -INFINITY};
        bool crosses = false;
        for (const Geometry& g : f.geometries)
            for (std::size_t i = 0; i < g.points.size(); ++i) {
                if (i > 0 && std::fabs(g.points[i].x - g.points[i - 1].x) > 180) crosses = true;
                Point q;
                if (!proj.project(g.points[i], q)) continue;
                const Point p = frame.to_pixel.apply(q);
                r = Rect{std::min(r.x0, p.x), std::min(r.y0, p.y), std::max(r.x1, p.x), std::max(r.y1, p.y)};
            }
        out.push_back(crosses ? Rect{-INFINITY, -INFINITY, INFINITY, INFINITY} : r);
    }
    return out;
}

// The geometry drawn window by window (see the top of the file): the original (simplify 0) from the
// features that reach each window; simplified, from all of them (the simplification depends on the
// neighbours; render_map leaves out the features that do not reach the window itself).
std::vector<std::uint8_t> windowed(const MapData& data, const std::vector<Rect>& bounds, const MapProjection& proj,
                                   const MapFrame& frame, const MapStyle& style, int window, double reach,
                                   double simplify) {
    MapOptions o;
    o.simplify = simplify;
    // Strokes through their outlines, round joins and caps within 0.001 px of their circles: at the
    // default tolerance (0.015 px) the inscribed arcs of a coastline's thousands of joins per pixel
    // would make the reference itself lose up to 0.3/255 on average at 256 px.
    o.sampled_strokes = false;
    o.tolerance = 0.001;
    std::vector<std::uint8_t> out(static_cast<std::size_t>(frame.width) * static_cast<std::size_t>(frame.height), 0);
    for (int ty = 0; ty < frame.height; ty += window)
        for (int tx = 0; tx < frame.width; tx += window) {
            MapFrame w;
            w.width = std::min(window, frame.width - tx);
            w.height = std::min(window, frame.height - ty);
            w.to_pixel = Affine{1, 0, 0, 1, -double(tx), -double(ty)} * frame.to_pixel;
            MapData part;
            if (simplify == 0) {
                for (std::size_t i = 0; i < data.features.size(); ++i) {
                    const Rect& b = bounds[i];
                    if (b.x1 >= tx - reach && b.x0 <= tx + w.width + reach && b.y1 >= ty - reach &&
                        b.y0 <= ty + w.height + reach)
                        part.features.push_back(data.features[i]);
                }
                if (part.features.empty()) continue;
            }
            Pixmap pm(w.width, w.height);
            render_map(simplify == 0 ? part : data, proj, w, style, o, pm);
            for (int y = 0; y < w.height; ++y)
                for (int x = 0; x < w.width; ++x)
                    out[static_cast<std::size_t>(ty + y) * frame.width + tx + x] = pm.pixel(x, y).a;
        }
    return out;
}

struct CoverageError {
    double mean = 0;
    int max = 0;
    std::size_t differ = 0;
};

CoverageError compare(const std::vector<std::uint8_t>& ref, const std::vector<std::uint8_t>& out) {
    CoverageError e;
    for (std::size_t i = 0; i < ref.size(); ++i) {
        const int d = std::abs(int(ref[i]) - int(out[i]));
        e.mean += d;
        e.max = std::max(e.max, d);
        e.differ += d != 0;
    }
    e.mean /= double(ref.size());
    return e;
}

}  // namespace

int run(int argc, char** argv) {
    std::string file, layer;
    std::vector<int> widths;
    std::vector<double> eps;
    int window = 64;
    double stroke_width = 0.8;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto next = [&]() -> const char* {
            if (i + 1 >= argc) throw std::runtime_error("missing value after " + a);
            return argv[++i];
        };
        if (a == "--layer")
            layer = next();
        else if (a == "--width")
            widths.push_back(std::atoi(next()));
        else if (a == "--simplify")
            eps.push_back(std::atof(next()));
        else if (a == "--window")
            window = std::atoi(next());
        else if (a == "--stroke-width")
            stroke_width = std::atof(next());
        else if (file.empty() && a[0] != '-')
            file = a;
        else
            throw std::runtime_error(
                "usage: map_accuracy FILE [--layer NAME] [--width W]... [--simplify E]... [--window T]");
    }
    if (file.empty())
        throw std::runtime_error("usage: map_accuracy FILE [--layer NAME] [--width W]... [--simplify E]...");
    if (widths.empty()) widths = {256, 4096};
    if (eps.empty()) eps = {kDefaultMapSimplify};
    const MapData data = read_map_file(file, layer);
    const MapProjection proj;
    std::printf("%s%s%s: %zu positions; reference: %s\n", file.c_str(), layer.empty() ? "" : " --layer ", layer.c_str(),
                data.position_count(),
                window > 0 ? ("the original drawn in windows of " + std::to_string(window) + " px").c_str()
                           : "the original, whole image");
    std::printf(
        "| size | picture | simplify (px) | output: mean error (/255) | max | pixels differing |"
        " simplification alone: mean | max |\n");
    std::printf("|---|---|---:|---:|---:|---:|---:|---:|\n");
    for (int w : widths) {
        MapOptions o;
        o.width = w;
        o.height = w / 2;
        o.bbox = Rect{-180, -90, 180, 90};
        MapFrame frame = fit_map(data, proj, o);
        const std::vector<Rect> bounds = feature_bounds(data, proj, frame);
        for (const Picture& p : pictures(stroke_width)) {
            const double reach = stroke_width * 2 + 2;
            const int side = window > 0 ? window : std::max(frame.width, frame.height);
            const std::vector<std::uint8_t> ref = windowed(data, bounds, proj, frame, p.style, side, reach, 0);
            std::vector<double> all = eps;
            if (window > 0) all.insert(all.begin(), 0.0);
            for (double e : all) {
                MapOptions oe = o;
                oe.simplify = e;
                Pixmap pm(frame.width, frame.height);
                render_map(data, proj, frame, p.style, oe, pm);
                const CoverageError out = compare(ref, alpha_of(pm));
                CoverageError alone;
                if (e > 0) alone = compare(ref, windowed(data, bounds, proj, frame, p.style, side, reach, e));
                std::printf("| %d x %d | %s | %g | %.3f | %d | %zu | %.3f | %d |\n", w, w / 2, p.name, e, out.mean,
                            out.max, out.differ, alone.mean, alone.max);
                std::fflush(stdout);
            }
        }
    }
    rusage ru{};
    getrusage(RUSAGE_SELF, &ru);
    std::printf("peak RSS %.0f MB\n", static_cast<double>(ru.ru_maxrss) / 1024.0);
    return 0;
}

int main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "map_accuracy: error: %s\n", e.what());
        return 1;
    }
}
