// Map stage: fitting the projected data to the image, the style's rules, and the entry points that
// draw a map (see include/casteljau/map.hpp; the drawing itself is in draw_map.cpp). Features are
// projected twice, once to measure the extent and once to draw, so that only one copy of the
// coordinates (the MapData) is ever held whole.
#include <algorithm>
#include <cmath>
#include <vector>

#include "casteljau/error.hpp"
#include "casteljau/map.hpp"
#include "core/for_each_index.hpp"
#include "map/draw_map.hpp"
#include "map/feature_paths.hpp"
#include "map/simplify_map.hpp"
#include "paint/pixmap_memory.hpp"

namespace casteljau {

namespace {

using map_detail::BoundsVisitor;
using map_detail::Projector;

Rect projected_bbox(const MapProjection& proj, const Rect& bb) {
    BoundsVisitor b;
    Point q;
    const int n = proj.preserves_graticule_lines() ? 1 : 64;
    for (int i = 0; i <= n; ++i) {
        const double t = static_cast<double>(i) / n;
        for (Point p : {Point{bb.x0 + (bb.x1 - bb.x0) * t, bb.y0}, Point{bb.x0 + (bb.x1 - bb.x0) * t, bb.y1},
                        Point{bb.x0, bb.y0 + (bb.y1 - bb.y0) * t}, Point{bb.x1, bb.y0 + (bb.y1 - bb.y0) * t}})
            if (proj.project(p, q)) b.add(q);
    }
    return b.r;
}

// sRGB components of a categorical palette (ColorBrewer-like "Set3"-style, readable on white).
const Color kPalette[] = {
    Color::rgba(141, 211, 199), Color::rgba(255, 237, 111), Color::rgba(190, 186, 218), Color::rgba(251, 128, 114),
    Color::rgba(128, 177, 211), Color::rgba(253, 180, 98),  Color::rgba(179, 222, 105), Color::rgba(252, 205, 229),
    Color::rgba(188, 128, 189), Color::rgba(204, 235, 197), Color::rgba(255, 255, 179), Color::rgba(217, 217, 217),
};

int compare(const PropertyValue& a, const PropertyValue& b, bool& comparable) {
    comparable = true;
    if (a.type == PropertyValue::Type::Number && b.type == PropertyValue::Type::Number)
        return a.number < b.number ? -1 : (a.number > b.number ? 1 : 0);
    if (a.type == PropertyValue::Type::Number || b.type == PropertyValue::Type::Number) {
        comparable = false;
        return 1;
    }
    const std::string x = a.to_string(), y = b.to_string();
    return x < y ? -1 : (x > y ? 1 : 0);
}

}  // namespace

bool MapFilter::matches(const Feature& f) const {
    if (op == Op::All) return true;
    const PropertyValue* v = f.property(property);
    if (op == Op::Has) return v != nullptr;
    if (!v) return op == Op::NotEquals;
    bool comparable = true;
    switch (op) {
        case Op::Equals: return !values.empty() && compare(*v, values[0], comparable) == 0 && comparable;
        case Op::NotEquals: return values.empty() || compare(*v, values[0], comparable) != 0 || !comparable;
        case Op::Less: return !values.empty() && compare(*v, values[0], comparable) < 0 && comparable;
        case Op::Greater: return !values.empty() && compare(*v, values[0], comparable) > 0 && comparable;
        case Op::In:
            for (const PropertyValue& x : values)
                if (compare(*v, x, comparable) == 0 && comparable) return true;
            return false;
        default: return true;
    }
}

Color ColorRamp::at(double v) const {
    double t = max > min ? (v - min) / (max - min) : (v >= max ? 1.0 : 0.0);
    t = std::clamp(t, 0.0, 1.0);
    auto mix = [t](std::uint8_t a, std::uint8_t b) {
        return static_cast<std::uint8_t>(std::lround(a + (static_cast<double>(b) - a) * t));
    };
    return Color::rgba(mix(min_color.r, max_color.r), mix(min_color.g, max_color.g), mix(min_color.b, max_color.b),
                       mix(min_color.a, max_color.a));
}

std::optional<Color> MapLayerStyle::fill_for(const Feature& f) const {
    if (!fill) return std::nullopt;
    if (fill_by.empty()) return fill;
    const PropertyValue* v = f.property(fill_by);
    if (!v || v->type == PropertyValue::Type::Null) return fill;
    if (ramp) {
        if (v->type != PropertyValue::Type::Number) return fill;
        return ramp->at(v->number);
    }
    const std::string key = v->to_string();
    std::uint32_t h = 2166136261u;  // FNV-1a
    for (char c : key) {
        h ^= static_cast<unsigned char>(c);
        h *= 16777619u;
    }
    if (!palette.empty()) return palette[h % palette.size()];
    return kPalette[h % (sizeof kPalette / sizeof kPalette[0])];
}

namespace {

void check_frame_options(const MapOptions& opts) {
    if (opts.width < 1) throw Error(ErrorKind::InvalidArgument, "map width must be at least 1 pixel");
    if (opts.height < 0) throw Error(ErrorKind::InvalidArgument, "map height must not be negative");
    if (!(opts.padding >= 0) || !std::isfinite(opts.padding))
        throw Error(ErrorKind::InvalidArgument, "padding must be a finite number >= 0");
}

// The projected extent to draw: the bbox's, or the data's bounds.
Rect map_extent(const MapData& data, const MapProjection& proj, const MapOptions& opts) {
    if (opts.bbox) {
        const Rect& b = *opts.bbox;
        if (!std::isfinite(b.x0) || !std::isfinite(b.x1) || !std::isfinite(b.y0) || !std::isfinite(b.y1) ||
            !(b.x0 < b.x1) || !(b.y0 < b.y1) || b.y0 < -90 || b.y1 > 90 || b.x0 < -540 || b.x1 > 540)
            throw Error(ErrorKind::InvalidArgument,
                        "bbox must be W,S,E,N degrees with W < E, S < N, latitudes within -90..90");
        const Rect ext = projected_bbox(proj, b);
        if (!(ext.x1 > ext.x0) || !(ext.y1 > ext.y0))
            throw Error(ErrorKind::InvalidArgument, "the bbox does not project to an area with this projection");
        return ext;
    }
    Projector pr(proj);
    BoundsVisitor b;
    for (const Feature& f : data.features)
        for (const Geometry& g : f.geometries) pr.geometry(g, b);
    if (!(b.r.x1 >= b.r.x0))
        throw Error(ErrorKind::InvalidData, "the map has no geometry to draw (pass --bbox to draw an empty extent)");
    return b.r;
}

// The extent with its width and height; one without width or height is made square around its
// line (a unit square around a point).
struct Extent {
    Rect r;
    double w, h;
};

Extent with_area(Rect ext) {
    const double ew = ext.width(), eh = ext.height();
    if (ew <= 0 && eh <= 0) return {Rect{ext.x0 - 0.5, ext.y0 - 0.5, ext.x0 + 0.5, ext.y0 + 0.5}, 1, 1};
    if (ew <= 0) return {Rect{ext.x0 - eh / 2, ext.y0, ext.x1 + eh / 2, ext.y1}, eh, eh};
    if (eh <= 0) return {Rect{ext.x0, ext.y0 - ew / 2, ext.x1, ext.y1 + ew / 2}, ew, ew};
    return {ext, ew, eh};
}

// The image's height: the given one, or `natural` (padding included) when none is; the padding
// must leave room inside it.
int frame_height(const MapOptions& opts, double natural) {
    const double h = opts.height > 0 ? opts.height : std::max(1.0, natural);
    check_canvas_size(opts.width, h);
    const int height = static_cast<int>(h);
    if (!(height - 2 * opts.padding > 0))
        throw Error(ErrorKind::InvalidArgument, "padding leaves no room in the image height");
    return height;
}

}  // namespace

MapFrame fit_map(const MapData& data, const MapProjection& proj, const MapOptions& opts) {
    check_frame_options(opts);
    const auto [ext, ew, eh] = with_area(map_extent(data, proj, opts));
    const double p = opts.padding;
    const double inner_w = opts.width - 2 * p;
    if (!(inner_w > 0)) throw Error(ErrorKind::InvalidArgument, "padding leaves no room in the image width");
    MapFrame fr;
    fr.width = opts.width;
    if (opts.bbox) {
        // The bbox fills the image exactly (non-uniform scale when both sizes are given).
        const double sx = inner_w / ew;
        fr.height = frame_height(opts, std::round(eh * sx + 2 * p));
        const double sy = (fr.height - 2 * p) / eh;
        fr.to_pixel = Affine{sx, 0, 0, -sy, p - ext.x0 * sx, p + ext.y1 * sy};
        return fr;
    }
    double s = inner_w / ew;
    fr.height = frame_height(opts, std::ceil(eh * s + 2 * p));
    const double inner_h = fr.height - 2 * p;
    s = std::min(s, inner_h / eh);
    // Centre the extent.
    const double ox = p + (inner_w - ew * s) / 2, oy = p + (inner_h - eh * s) / 2;
    fr.to_pixel = Affine{s, 0, 0, -s, ox - ext.x0 * s, oy + ext.y1 * s};
    return fr;
}

int map_threads(int requested) {
    if (requested < 0 || requested > 256)
        throw Error(ErrorKind::InvalidArgument, "threads must be 0 (all cores) to 256");
    const int pool = parallel::thread_count();
    return requested > 0 ? std::min(requested, pool) : pool;
}

void render_map(const MapData& data, const MapProjection& proj, const MapFrame& frame, const MapStyle& style,
                const MapOptions& opts, Pixmap& target) {
    map_detail::KeptMap* cache = opts.cache ? &map_detail::MapCacheAccess::bind(*opts.cache, data, proj) : nullptr;
    map_detail::draw_map(data, nullptr, proj, frame, style, opts, target, false, cache);
}

namespace map_detail {

void render_simplified_map(const MapData& data, const SimplifiedMap& simplified, const MapProjection& proj,
                           const MapFrame& frame, const MapStyle& style, const MapOptions& opts, Pixmap& target) {
    draw_map(data, &simplified, proj, frame, style, opts, target, false);
}

}  // namespace map_detail

Pixmap render_map(const MapData& data, const MapProjection& proj, const MapStyle& style, const MapOptions& opts) {
    const MapFrame fr = fit_map(data, proj, opts);
    // The memory of a released image of this size is cleared by draw_map, band by band on its
    // workers, rather than here on one thread.
    bool zero = false;
    Pixmap pm = PixmapMemory::uncleared(fr.width, fr.height, zero);
    map_detail::KeptMap* cache = opts.cache ? &map_detail::MapCacheAccess::bind(*opts.cache, data, proj) : nullptr;
    map_detail::draw_map(data, nullptr, proj, fr, style, opts, pm, zero, cache);
    return pm;
}

}  // namespace casteljau
