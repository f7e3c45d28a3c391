// `casteljau map`: render GeoJSON / GeoJSON lines / TopoJSON to PNG through a projection.
#include <cmath>
#include <sstream>

#include "casteljau/error.hpp"
#include "casteljau/geojson.hpp"
#include "casteljau/limits.hpp"
#include "casteljau/map.hpp"
#include "casteljau/png.hpp"
#include "casteljau/projection.hpp"
#include "casteljau/threads.hpp"
#include "cli/cli.hpp"

namespace casteljau::cli {

namespace {

bool ends_with(const std::string& s, const std::string& suffix) {
    return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

Rect parse_bbox(const std::string& text) {
    std::string s = text;
    for (char& c : s)
        if (c == ',') c = ' ';
    std::istringstream in(s);
    double v[4];
    for (double& x : v)
        if (!(in >> x) || !std::isfinite(x))
            throw UsageError("--bbox: expected W,S,E,N in degrees, got '" + text + "'");
    std::string rest;
    if (in >> rest) throw UsageError("--bbox: expected four numbers W,S,E,N, got '" + text + "'");
    if (!(v[0] < v[2]) || !(v[1] < v[3]) || v[1] < -90 || v[3] > 90)
        throw UsageError("--bbox: need W < E and -90 <= S < N <= 90, got '" + text + "'");
    return Rect{v[0], v[1], v[2], v[3]};
}

ColorRamp parse_ramp(const std::string& text) {
    // MIN:COLOR,MAX:COLOR (colours may contain commas inside rgb(...): split at the top level).
    std::vector<std::string> parts;
    int depth = 0;
    std::string cur;
    for (char c : text) {
        if (c == '(') ++depth;
        if (c == ')') --depth;
        if (c == ',' && depth == 0) {
            parts.push_back(cur);
            cur.clear();
        } else {
            cur += c;
        }
    }
    parts.push_back(cur);
    if (parts.size() != 2) throw UsageError("--ramp: expected MIN:COLOR,MAX:COLOR, got '" + text + "'");
    ColorRamp r;
    for (int i = 0; i < 2; ++i) {
        const auto colon = parts[i].find(':');
        if (colon == std::string::npos) throw UsageError("--ramp: expected VALUE:COLOR, got '" + parts[i] + "'");
        char* end = nullptr;
        const std::string num = parts[i].substr(0, colon);
        const double v = std::strtod(num.c_str(), &end);
        if (num.empty() || *end != '\0' || !std::isfinite(v)) throw UsageError("--ramp: bad number '" + num + "'");
        const Color c = parse_color_option("--ramp", parts[i].substr(colon + 1));
        if (i == 0) {
            r.min = v;
            r.min_color = c;
        } else {
            r.max = v;
            r.max_color = c;
        }
    }
    if (!(r.min < r.max)) throw UsageError("--ramp: MIN must be below MAX");
    return r;
}

}  // namespace

MapData read_map_input(const std::string& path, const std::string& layer) {
    if (ends_with(path, ".geojsonl") || ends_with(path, ".geojsons") || ends_with(path, ".ndjson") ||
        ends_with(path, ".geojsonseq")) {
        if (!layer.empty()) throw UsageError("--layer selects a TopoJSON object, but the input is GeoJSON lines");
        return read_geojson_lines(read_text_input(path));
    }
    if (ends_with(path, ".topojson")) return read_topojson(read_text_input(path), layer);
    if (path == "-") return read_map_data(read_text_input(path), layer);
    return read_map_file(path, layer);  // parsed in place, the text released before MapData is built
}

void add_map_style_options(CLI::App* cmd, MapCliStyle& o) {
    cmd->add_option("--fill", o.fill, "Fill colour (CSS syntax, 'none' for no fill)")->capture_default_str();
    cmd->add_option("--stroke", o.stroke, "Stroke colour of outlines and lines (default: none)");
    cmd->add_option("--stroke-width", o.stroke_width, "Stroke width in pixels")
        ->check(CLI::Range(0.0, 1e4))
        ->capture_default_str();
    cmd->add_option("--line-join", o.join, "round, miter or bevel")
        ->check(CLI::IsMember({"round", "miter", "bevel"}))
        ->capture_default_str();
    cmd->add_option("--line-cap", o.cap, "round, butt or square")
        ->check(CLI::IsMember({"round", "butt", "square"}))
        ->capture_default_str();
    cmd->add_option("--background", o.background, "Background colour (CSS syntax)")->capture_default_str();
    cmd->add_option("--fill-by", o.fill_by, "Property giving each feature's fill (categorical palette, or --ramp)");
    cmd->add_option("--ramp", o.ramp, "Numeric ramp for --fill-by: MIN:COLOR,MAX:COLOR");
    cmd->add_option("--point-radius", o.point_radius, "Radius of Point disks in pixels")
        ->check(CLI::Range(0.0, 1e4))
        ->capture_default_str();
    cmd->add_option("--opacity", o.opacity, "Opacity of fills and strokes")->check(CLI::Range(0.0, 1.0));
    cmd->add_option("--style", o.style_file, "JSON style file (layers with filters); replaces the colour options");
    cmd->add_option("--projection", o.projection,
                    "equirectangular, mercator, a PROJ string ('+proj=robin') or a CRS ('EPSG:3035')")
        ->capture_default_str();
    cmd->add_option("--layer", o.layer, "TopoJSON object to draw (default: all)");
    cmd->add_flag("--separate", o.separate, "Draw each fill on its own with source-over (seams between neighbours)");
    cmd->add_flag("--no-exact-overlaps", o.no_exact,
                  "Fills by plain accumulation (about 3x faster on dense data; exact for valid polygons)");
    cmd->add_flag("--exact-strokes", o.exact_strokes,
                  "Round strokes up to 64 px wide through their outlines, exact (default: the union of their "
                  "segments' capsules, within 4/255 per horizontal border; far faster on dense maps)");
    cmd->add_option("--tolerance", o.tolerance, "Flattening tolerance in pixels")
        ->check(CLI::Range(1e-4, 10.0))
        ->capture_default_str();
    cmd->add_option("--simplify", o.simplify,
                    "Pixels the geometry may move when reduced to the output's resolution (0: every position; "
                    "sparse data are drawn as they are)")
        ->check(CLI::Range(0.0, 100.0))
        ->capture_default_str();
}

MapStyle build_map_style(const MapCliStyle& o) {
    MapStyle st;
    if (!o.style_file.empty()) {
        st = read_map_style(read_text_input(o.style_file));
    } else {
        MapLayerStyle& l = st.layers.at(0);
        const Color f = parse_color_option("--fill", o.fill);
        if (o.fill == "none")
            l.fill.reset();
        else
            l.fill = f;
        if (!o.stroke.empty() && o.stroke != "none") l.stroke = parse_color_option("--stroke", o.stroke);
        l.stroke_width = o.stroke_width;
        l.opacity = o.opacity;
        l.fill_by = o.fill_by;
        if (!o.ramp.empty()) {
            if (o.fill_by.empty()) throw UsageError("--ramp needs --fill-by PROPERTY");
            l.ramp = parse_ramp(o.ramp);
        }
        st.background = parse_color_option("--background", o.background);
        st.point_radius = o.point_radius;
    }
    parse_line_join(o.join, st.join);  // the option checks only admit valid names
    parse_line_cap(o.cap, st.cap);
    if (!o.style_file.empty() && o.background != "transparent")
        st.background = parse_color_option("--background", o.background);
    return st;
}

void register_map(CLI::App& app) {
    struct Opts {
        std::string input, output, bbox;
        int width = 0, height = 0;
        double padding = 0;
        int threads = 0;
        MapCliStyle style;
    };
    auto o = std::make_shared<Opts>();
    CLI::App* cmd = app.add_subcommand("map", "Render GeoJSON, GeoJSON lines or TopoJSON to PNG");
    cmd->add_option("INPUT", o->input, "Map file: .geojson, .json, .topojson, .geojsonl (- for standard input)")
        ->required();
    cmd->add_option("-o,--output", o->output, "Output PNG file")->required();
    cmd->add_option("--width", o->width, "Image width in pixels")
        ->required()
        ->check(CLI::Range(1, limits::kMaxCanvasDimension));
    cmd->add_option("--height", o->height, "Image height in pixels (default: from the extent's aspect ratio)")
        ->check(CLI::Range(1, limits::kMaxCanvasDimension));
    cmd->add_option("--bbox", o->bbox, "Extent W,S,E,N in degrees mapped exactly onto the image");
    cmd->add_option("--padding", o->padding, "Padding in pixels around the data extent")
        ->check(CLI::Range(0.0, 1e5))
        ->capture_default_str();
    cmd->add_option("--threads", o->threads, "Threads (default: all cores; the image is the same for any number)")
        ->check(CLI::Range(1, 256));
    add_map_style_options(cmd, o->style);
    cmd->callback([o] {
        MapOptions mo;
        if (o->threads > 0) set_thread_count(o->threads);  // the pool the bands are drawn on
        mo.threads = 0;
        mo.width = o->width;
        mo.height = o->height;
        mo.padding = o->padding;
        mo.seamless = !o->style.separate;
        mo.tolerance = o->style.tolerance;
        mo.simplify = o->style.simplify;
        mo.exact_overlaps = !o->style.no_exact;
        mo.sampled_strokes = !o->style.exact_strokes;
        if (!o->bbox.empty()) mo.bbox = parse_bbox(o->bbox);
        const MapStyle style = build_map_style(o->style);
        const MapProjection proj = MapProjection::parse(o->style.projection);
        const MapData data = read_map_input(o->input, o->style.layer);
        const Pixmap pm = render_map(data, proj, style, mo);
        write_png(pm, o->output);
    });
}

}  // namespace casteljau::cli
