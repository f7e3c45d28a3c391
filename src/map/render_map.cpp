// Map stage: fitting the projected data to the image and drawing the features (see
// include/casteljau/map.hpp). Features are projected twice, once to measure the extent and once
// to draw, so that only one copy of the coordinates (the MapData) is ever held: the pixel-space
// Path of one feature lives only while that feature is drawn.
#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include "casteljau/canvas.hpp"
#include "casteljau/error.hpp"
#include "casteljau/map.hpp"
#include "casteljau/seamless.hpp"

namespace casteljau {

namespace {

// Densify step for projections that bend straight lon/lat segments (degrees).
constexpr double kDensifyDegrees = 1.0;

// Visits the projected pieces of one geometry: polygon rings (oriented: exteriors positive signed
// area in lon/lat, holes negative), lines, and points, in projected coordinates.
struct PieceVisitor {
    virtual ~PieceVisitor() = default;
    virtual void ring(const std::vector<Point>& pts) = 0;
    virtual void line(const std::vector<Point>& pts) = 0;
    virtual void point(Point p) = 0;
};

double ring_area2(std::span<const Point> r) {
    double s = 0;
    const std::size_t n = r.size();
    for (std::size_t i = 0; i + 1 < n; ++i) s += r[i].x * r[i + 1].y - r[i + 1].x * r[i].y;
    if (n > 0) s += r[n - 1].x * r[0].y - r[0].x * r[n - 1].y;
    return s;
}

class Projector {
public:
    explicit Projector(const MapProjection& p) : proj_(p), densify_(!p.preserves_graticule_lines()) {}

    // Projects a lon/lat polyline into `out` (points that cannot be projected are dropped).
    void project(const std::vector<Point>& in, bool closed, std::vector<Point>& out) const {
        out.clear();
        out.reserve(in.size());
        Point q;
        const std::size_t n = in.size();
        const std::size_t segs = closed ? n : (n == 0 ? 0 : n - 1);
        if (!densify_) {
            for (const Point& p : in)
                if (proj_.project(p, q)) out.push_back(q);
            return;
        }
        for (std::size_t i = 0; i < n; ++i) {
            if (proj_.project(in[i], q)) out.push_back(q);
            if (i >= segs) continue;
            const Point a = in[i], b = in[(i + 1) % n];
            const double len = std::max(std::fabs(b.x - a.x), std::fabs(b.y - a.y));
            const int steps = static_cast<int>(std::ceil(len / kDensifyDegrees));
            for (int s = 1; s < steps && steps <= 4096; ++s)
                if (proj_.project(lerp(a, b, static_cast<double>(s) / steps), q)) out.push_back(q);
        }
    }

    void geometry(const Geometry& g, PieceVisitor& v) const {
        Point q;
        if (g.kind == GeometryKind::Points) {
            for (const Point& p : g.points)
                if (proj_.project(p, q)) v.point(q);
            return;
        }
        std::size_t start = 0;
        if (g.kind == GeometryKind::Lines) {
            for (std::uint32_t end : g.ring_ends) {
                pieces_.clear();
                split_line_at_antimeridian(std::span<const Point>(g.points).subspan(start, end - start), pieces_);
                for (const auto& piece : pieces_) {
                    project(piece, false, projected_);
                    if (projected_.size() >= 2) v.line(projected_);
                }
                start = end;
            }
            return;
        }
        std::size_t ring = 0;
        for (std::uint32_t pend : g.polygon_ends) {
            for (bool exterior = true; ring < pend; ++ring, exterior = false) {
                const std::uint32_t end = g.ring_ends[ring];
                std::span<const Point> r = std::span<const Point>(g.points).subspan(start, end - start);
                start = end;
                pieces_.clear();
                split_ring_at_antimeridian(r, pieces_);
                for (auto& piece : pieces_) {
                    // Exteriors counter-clockwise in lon/lat (positive area), holes clockwise.
                    const double a = ring_area2(piece);
                    if ((exterior && a < 0) || (!exterior && a > 0)) std::reverse(piece.begin(), piece.end());
                    project(piece, true, projected_);
                    if (projected_.size() >= 3) v.ring(projected_);
                }
            }
        }
    }

private:
    const MapProjection& proj_;
    bool densify_;
    mutable std::vector<std::vector<Point>> pieces_;
    mutable std::vector<Point> projected_;
};

struct BoundsVisitor final : PieceVisitor {
    Rect r{INFINITY, INFINITY, -INFINITY, -INFINITY};
    void add(Point p) {
        r.x0 = std::min(r.x0, p.x); r.y0 = std::min(r.y0, p.y);
        r.x1 = std::max(r.x1, p.x); r.y1 = std::max(r.y1, p.y);
    }
    void ring(const std::vector<Point>& pts) override { for (const Point& p : pts) add(p); }
    void line(const std::vector<Point>& pts) override { for (const Point& p : pts) add(p); }
    void point(Point p) override { add(p); }
};

// Builds the pixel-space paths of one feature.
struct PathVisitor final : PieceVisitor {
    Affine m;
    double point_radius = 3;
    Path fill;   // polygons + point disks
    Path lines;  // open polylines, to be stroked
    void ring(const std::vector<Point>& pts) override {
        fill.move_to(m.apply(pts[0]));
        for (std::size_t i = 1; i < pts.size(); ++i) fill.line_to(m.apply(pts[i]));
        fill.close();
    }
    void line(const std::vector<Point>& pts) override {
        lines.move_to(m.apply(pts[0]));
        for (std::size_t i = 1; i < pts.size(); ++i) lines.line_to(m.apply(pts[i]));
    }
    void point(Point p) override {
        if (point_radius > 0) fill.add_circle(m.apply(p), point_radius);
    }
};

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

MapFrame fit_map(const MapData& data, const MapProjection& proj, const MapOptions& opts) {
    if (opts.width < 1) throw Error(ErrorKind::InvalidArgument, "map width must be at least 1 pixel");
    if (opts.height < 0) throw Error(ErrorKind::InvalidArgument, "map height must not be negative");
    if (!(opts.padding >= 0) || !std::isfinite(opts.padding))
        throw Error(ErrorKind::InvalidArgument, "padding must be a finite number >= 0");
    Rect ext;
    if (opts.bbox) {
        const Rect& b = *opts.bbox;
        if (!std::isfinite(b.x0) || !std::isfinite(b.x1) || !std::isfinite(b.y0) || !std::isfinite(b.y1) || !(b.x0 < b.x1) ||
            !(b.y0 < b.y1) || b.y0 < -90 || b.y1 > 90 || b.x0 < -540 || b.x1 > 540)
            throw Error(ErrorKind::InvalidArgument,
                        "bbox must be W,S,E,N degrees with W < E, S < N, latitudes within -90..90");
        ext = projected_bbox(proj, b);
        if (!(ext.x1 > ext.x0) || !(ext.y1 > ext.y0))
            throw Error(ErrorKind::InvalidArgument, "the bbox does not project to an area with this projection");
    } else {
        Projector pr(proj);
        BoundsVisitor b;
        for (const Feature& f : data.features)
            for (const Geometry& g : f.geometries) pr.geometry(g, b);
        if (!(b.r.x1 >= b.r.x0))
            throw Error(ErrorKind::InvalidData, "the map has no geometry to draw (pass --bbox to draw an empty extent)");
        ext = b.r;
    }
    double ew = ext.width(), eh = ext.height();
    if (ew <= 0 && eh <= 0) {  // a single point: a unit extent around it
        ew = eh = 1;
        ext = Rect{ext.x0 - 0.5, ext.y0 - 0.5, ext.x0 + 0.5, ext.y0 + 0.5};
    } else if (ew <= 0) {
        ext.x0 -= eh / 2; ext.x1 += eh / 2; ew = eh;
    } else if (eh <= 0) {
        ext.y0 -= ew / 2; ext.y1 += ew / 2; eh = ew;
    }
    const double p = opts.padding;
    const double inner_w = opts.width - 2 * p;
    if (!(inner_w > 0)) throw Error(ErrorKind::InvalidArgument, "padding leaves no room in the image width");
    MapFrame fr;
    fr.width = opts.width;
    if (opts.bbox) {
        // The bbox fills the image exactly (non-uniform scale when both sizes are given).
        const double sx = inner_w / ew;
        const double h = opts.height > 0 ? opts.height : std::max(1.0, std::round(eh * sx + 2 * p));
        check_canvas_size(opts.width, h);
        fr.height = static_cast<int>(h);
        const double inner_h = fr.height - 2 * p;
        if (!(inner_h > 0)) throw Error(ErrorKind::InvalidArgument, "padding leaves no room in the image height");
        const double sy = inner_h / eh;
        fr.to_pixel = Affine{sx, 0, 0, -sy, p - ext.x0 * sx, p + ext.y1 * sy};
        return fr;
    }
    double s = inner_w / ew;
    double h = opts.height;
    if (h <= 0) h = std::max(1.0, std::ceil(eh * s + 2 * p));
    check_canvas_size(opts.width, h);
    fr.height = static_cast<int>(h);
    const double inner_h = fr.height - 2 * p;
    if (!(inner_h > 0)) throw Error(ErrorKind::InvalidArgument, "padding leaves no room in the image height");
    s = std::min(s, inner_h / eh);
    // Centre the extent.
    const double ox = p + (inner_w - ew * s) / 2, oy = p + (inner_h - eh * s) / 2;
    fr.to_pixel = Affine{s, 0, 0, -s, ox - ext.x0 * s, oy + ext.y1 * s};
    return fr;
}

void render_map(const MapData& data, const MapProjection& proj, const MapFrame& frame, const MapStyle& style,
                const MapOptions& opts, Pixmap& target) {
    if (target.width() != frame.width || target.height() != frame.height)
        throw Error(ErrorKind::InvalidArgument, "render_map: the pixmap does not have the frame's size");
    target.fill(style.background);
    Canvas canvas(target);
    canvas.fill_options().tolerance = opts.tolerance;
    FillOptions fo;
    fo.rule = opts.fill_rule;
    fo.tolerance = opts.tolerance;
    fo.exact_overlaps = opts.exact_overlaps;
    Projector pr(proj);
    Rasterizer& raster = canvas.rasterizer();
    StrokeStyle ss;
    ss.join = style.join;
    ss.cap = style.cap;
    ss.miter_limit = style.miter_limit;
    std::optional<AreaCompositor> area;

    auto build = [&](const Feature& f, PathVisitor& v) {
        v.m = frame.to_pixel;
        v.point_radius = style.point_radius;
        for (const Geometry& g : f.geometries) pr.geometry(g, v);
    };
    // The pixel-space fill of feature `f` in `layer` with its colour, or nullopt when the layer's
    // filter or colour leaves it out or it has no area.
    auto fill_of = [&](const MapLayerStyle& layer, const Feature& f) -> std::optional<std::pair<Path, Color>> {
        if (!layer.filter.matches(f)) return std::nullopt;
        const std::optional<Color> c = layer.fill_for(f);
        if (!c) return std::nullopt;
        PathVisitor v;
        build(f, v);
        if (v.fill.empty()) return std::nullopt;
        return std::pair<Path, Color>{std::move(v.fill), *c};
    };

    for (const MapLayerStyle& layer : style.layers) {
        // Fills: seamless (by area, last feature first so that later features win) or source-over in order.
        const bool any_fill = layer.fill.has_value();
        if (any_fill && opts.seamless) {
            if (!area) area.emplace(frame.width, frame.height);
            else area->clear();
            bool drew = false;
            for (std::size_t i = data.features.size(); i-- > 0;) {
                const auto fill = fill_of(layer, data.features[i]);
                if (!fill) continue;
                area->add(raster, fill->first, fo, fill->second, layer.opacity);
                drew = true;
            }
            if (drew) area->composite_onto(target);
        } else if (any_fill) {
            canvas.fill_options().exact_overlaps = opts.exact_overlaps;
            for (const Feature& f : data.features) {
                const auto fill = fill_of(layer, f);
                if (!fill) continue;
                Paint paint = Paint::solid(fill->second);
                paint.opacity = layer.opacity;
                canvas.fill_path(fill->first, paint, opts.fill_rule);
            }
        }
        // Strokes: one outline path per colour, filled once (shared borders drawn once).
        const std::optional<Color> line_color = layer.stroke ? layer.stroke : layer.fill;
        if (!line_color || !(layer.stroke_width > 0)) continue;
        Path outline;
        auto flush = [&] {
            if (outline.empty()) return;
            Paint paint = Paint::solid(*line_color);
            paint.opacity = layer.opacity;
            canvas.fill_options().exact_overlaps = true;  // a shared border's two copies must not add up
            canvas.fill_path(outline, paint, FillRule::NonZero);
            outline.clear();
        };
        ss.width = layer.stroke_width;
        for (const Feature& f : data.features) {
            if (!layer.filter.matches(f)) continue;
            PathVisitor v;
            build(f, v);
            if (layer.stroke && !v.fill.empty()) {
                // Polygon outlines (point disks too) with the stroke colour.
                const Path o = stroke(v.fill, ss, Affine{}, opts.tolerance);
                if (outline.points().size() + o.points().size() > limits::kMaxPathPoints / 2) flush();
                outline.append(o);
            }
            if (!v.lines.empty()) {
                const Path o = stroke(v.lines, ss, Affine{}, opts.tolerance);
                if (outline.points().size() + o.points().size() > limits::kMaxPathPoints / 2) flush();
                outline.append(o);
            }
        }
        flush();
    }
}

Pixmap render_map(const MapData& data, const MapProjection& proj, const MapStyle& style, const MapOptions& opts) {
    const MapFrame fr = fit_map(data, proj, opts);
    Pixmap pm(fr.width, fr.height);
    render_map(data, proj, fr, style, opts, pm);
    return pm;
}

}  // namespace casteljau
