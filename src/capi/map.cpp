// C API: map data and map images (casteljau_map.h), read and drawn the way `casteljau map` does.
#include <cmath>
#include <string>
#include <string_view>

#include "capi/handles.hpp"
#include "casteljau/file_io.hpp"

using namespace casteljau;
using casteljau::capi::check_range;
using casteljau::capi::create;
using casteljau::capi::guard;
using casteljau::capi::need;

namespace {

bool ends_with(std::string_view s, std::string_view suffix) {
    return s.size() >= suffix.size() && s.substr(s.size() - suffix.size()) == suffix;
}

// The reader the command line picks for a file: by its extension, else by its content.
MapData read_map_path(const std::string& path, const std::string& layer) {
    if (ends_with(path, ".geojsonl") || ends_with(path, ".geojsons") || ends_with(path, ".ndjson") ||
        ends_with(path, ".geojsonseq")) {
        if (!layer.empty())
            throw Error(ErrorKind::InvalidArgument,
                        "a layer selects a TopoJSON object, but the input is GeoJSON lines");
        const std::vector<std::uint8_t> bytes = read_file(path);
        return read_geojson_lines(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
    }
    if (ends_with(path, ".topojson")) {
        const std::vector<std::uint8_t> bytes = read_file(path);
        return read_topojson(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), layer);
    }
    return read_map_file(path, layer);
}

template <class F>
casteljau_status edit_layers(casteljau_map_style* style, F&& f) noexcept {
    return guard([&] {
        for (MapLayerStyle& l : need(style, "style")->style.layers) f(l);
    });
}

template <class F>
casteljau_status edit_style(casteljau_map_style* style, F&& f) noexcept {
    return guard([&] { f(need(style, "style")->style); });
}

template <class F>
casteljau_status edit_options(casteljau_map_options* options, F&& f) noexcept {
    return guard([&] { f(*need(options, "options")); });
}

// The map image of `options` (its size, or `fallback_width` x `fallback_height` when it has none).
Pixmap map_image(const casteljau_map* map, const casteljau_map_style* style, const casteljau_map_options* options,
                 int fallback_width = 0, int fallback_height = 0) {
    const MapData& data = need(map, "map")->data;
    const casteljau_map_options& o = *need(options, "options");
    MapOptions mo = o.options;
    if (mo.width == 0) {
        mo.width = fallback_width;
        mo.height = fallback_height;
    }
    if (mo.width < 1)
        throw Error(ErrorKind::InvalidArgument, "the map options have no size (casteljau_map_options_set_size)");
    return render_map(data, o.projection, style ? style->style : MapStyle{}, mo);
}

}  // namespace

extern "C" {

casteljau_status casteljau_map_load(const char* path, const char* layer, casteljau_map** out) {
    return create(out, [&] { return read_map_path(need(path, "path"), casteljau::capi::text_or_empty(layer)); });
}

casteljau_status casteljau_map_parse(const char* text, size_t size, const char* layer, casteljau_map** out) {
    return create(out, [&] {
        if (size > 0) need(text, "text");
        return read_map_data(std::string_view(text, size), casteljau::capi::text_or_empty(layer));
    });
}

void casteljau_map_destroy(casteljau_map* map) { delete map; }

size_t casteljau_map_feature_count(const casteljau_map* map) { return map ? map->data.features.size() : 0; }

casteljau_map_style* casteljau_map_style_create(void) { return casteljau::capi::create_default<casteljau_map_style>(); }

casteljau_status casteljau_map_style_load(const char* path, casteljau_map_style** out) {
    return create(out, [&] {
        const std::vector<std::uint8_t> bytes = read_file(need(path, "path"));
        return read_map_style(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
    });
}

casteljau_status casteljau_map_style_parse(const char* json, casteljau_map_style** out) {
    return create(out, [&] { return read_map_style(need(json, "json")); });
}

void casteljau_map_style_destroy(casteljau_map_style* style) { delete style; }

casteljau_status casteljau_map_style_set_fill(casteljau_map_style* style, const casteljau_color* fill) {
    return edit_layers(style, [&](MapLayerStyle& l) {
        if (fill)
            l.fill = casteljau::capi::color(*fill);
        else
            l.fill.reset();
    });
}

casteljau_status casteljau_map_style_set_stroke(casteljau_map_style* style, const casteljau_color* stroke) {
    return edit_layers(style, [&](MapLayerStyle& l) {
        if (stroke)
            l.stroke = casteljau::capi::color(*stroke);
        else
            l.stroke.reset();
    });
}

casteljau_status casteljau_map_style_set_stroke_width(casteljau_map_style* style, double width) {
    return edit_layers(style, [&](MapLayerStyle& l) {
        check_range(width, 0, 1e4, "stroke width");
        l.stroke_width = width;
    });
}

casteljau_status casteljau_map_style_set_opacity(casteljau_map_style* style, double opacity) {
    return edit_layers(style, [&](MapLayerStyle& l) {
        check_range(opacity, 0, 1, "opacity");
        l.opacity = opacity;
    });
}

casteljau_status casteljau_map_style_set_fill_by(casteljau_map_style* style, const char* property) {
    return edit_layers(style, [&](MapLayerStyle& l) { l.fill_by = casteljau::capi::text_or_empty(property); });
}

casteljau_status casteljau_map_style_set_ramp(casteljau_map_style* style, double min, casteljau_color min_color,
                                              double max, casteljau_color max_color) {
    return edit_layers(style, [&](MapLayerStyle& l) {
        if (!std::isfinite(min) || !std::isfinite(max) || !(min < max))
            throw Error(ErrorKind::InvalidArgument, "a ramp needs finite values with min < max");
        l.ramp = ColorRamp{min, max, casteljau::capi::color(min_color), casteljau::capi::color(max_color)};
    });
}

casteljau_status casteljau_map_style_set_background(casteljau_map_style* style, casteljau_color background) {
    return edit_style(style, [&](MapStyle& s) { s.background = casteljau::capi::color(background); });
}

casteljau_status casteljau_map_style_set_line_join(casteljau_map_style* style, casteljau_line_join join) {
    return edit_style(style, [&](MapStyle& s) {
        const int j = casteljau::capi::raw_enum(join);
        if (j < CASTELJAU_JOIN_MITER || j > CASTELJAU_JOIN_BEVEL)
            throw Error(ErrorKind::InvalidArgument, "unknown line join");
        s.join = static_cast<LineJoin>(j);
    });
}

casteljau_status casteljau_map_style_set_line_cap(casteljau_map_style* style, casteljau_line_cap cap) {
    return edit_style(style, [&](MapStyle& s) {
        const int c = casteljau::capi::raw_enum(cap);
        if (c < CASTELJAU_CAP_BUTT || c > CASTELJAU_CAP_SQUARE)
            throw Error(ErrorKind::InvalidArgument, "unknown line cap");
        s.cap = static_cast<LineCap>(c);
    });
}

casteljau_status casteljau_map_style_set_point_radius(casteljau_map_style* style, double radius) {
    return edit_style(style, [&](MapStyle& s) {
        check_range(radius, 0, 1e4, "point radius");
        s.point_radius = radius;
    });
}

casteljau_map_options* casteljau_map_options_create(void) {
    return casteljau::capi::create_default<casteljau_map_options>();
}

void casteljau_map_options_destroy(casteljau_map_options* options) { delete options; }

casteljau_status casteljau_map_options_set_size(casteljau_map_options* options, int width, int height) {
    return edit_options(options, [&](casteljau_map_options& o) {
        check_range(width, 1, limits::kMaxCanvasDimension, "map width");
        check_range(height, 0, limits::kMaxCanvasDimension, "map height");
        o.options.width = width;
        o.options.height = height;
    });
}

casteljau_status casteljau_map_options_set_projection(casteljau_map_options* options, const char* projection) {
    return edit_options(options, [&](casteljau_map_options& o) {
        o.projection = MapProjection::parse(need(projection, "projection"));
    });
}

casteljau_status casteljau_map_options_set_bbox(casteljau_map_options* options, double west, double south, double east,
                                                double north) {
    return edit_options(options, [&](casteljau_map_options& o) {
        if (!std::isfinite(west) || !std::isfinite(south) || !std::isfinite(east) || !std::isfinite(north) ||
            !(west < east) || !(south < north) || south < -90 || north > 90)
            throw Error(ErrorKind::InvalidArgument, "a bbox needs finite west < east and -90 <= south < north <= 90");
        o.options.bbox = Rect{west, south, east, north};
    });
}

casteljau_status casteljau_map_options_set_padding(casteljau_map_options* options, double pixels) {
    return edit_options(options, [&](casteljau_map_options& o) {
        check_range(pixels, 0, 1e5, "padding");
        o.options.padding = pixels;
    });
}

casteljau_status casteljau_map_options_set_separate(casteljau_map_options* options, int separate) {
    return edit_options(options, [&](casteljau_map_options& o) { o.options.seamless = separate == 0; });
}

casteljau_status casteljau_map_options_set_exact_overlaps(casteljau_map_options* options, int exact) {
    return edit_options(options, [&](casteljau_map_options& o) { o.options.exact_overlaps = exact != 0; });
}

casteljau_status casteljau_map_options_set_tolerance(casteljau_map_options* options, double tolerance) {
    return edit_options(options, [&](casteljau_map_options& o) {
        check_range(tolerance, 1e-4, 10, "tolerance");
        o.options.tolerance = tolerance;
    });
}

casteljau_map_cache* casteljau_map_cache_create(void) { return casteljau::capi::create_default<casteljau_map_cache>(); }

void casteljau_map_cache_destroy(casteljau_map_cache* cache) { delete cache; }

casteljau_status casteljau_map_options_set_cache(casteljau_map_options* options, casteljau_map_cache* cache) {
    return edit_options(options, [&](casteljau_map_options& o) { o.options.cache = cache ? &cache->cache : nullptr; });
}

casteljau_status casteljau_map_render_image(const casteljau_map* map, const casteljau_map_style* style,
                                            const casteljau_map_options* options, casteljau_image** out) {
    return create(out, [&] { return map_image(map, style, options); });
}

casteljau_status casteljau_map_render(const casteljau_map* map, const casteljau_map_style* style,
                                      const casteljau_map_options* options, casteljau_canvas* canvas) {
    return guard([&] {
        Canvas& c = *need(canvas, "canvas")->canvas;
        c.draw_image(map_image(map, style, options, c.width(), c.height()));
    });
}

}  // extern "C"
