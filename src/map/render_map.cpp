// Map stage: fitting the projected data to the image and drawing the features (see
// include/casteljau/map.hpp). Features are projected twice, once to measure the extent and once
// to draw, so that only one copy of the coordinates (the MapData) is ever held whole: the
// pixel-space paths exist a chunk of features at a time. Each chunk is projected by all threads
// (a feature each), then drawn by all threads (a horizontal band of the image each).
#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "casteljau/canvas.hpp"
#include "casteljau/error.hpp"
#include "casteljau/limits.hpp"
#include "casteljau/map.hpp"
#include "casteljau/round_stroke.hpp"
#include "casteljau/seamless.hpp"
#include "core/for_each_index.hpp"
#include "map/clip_to_frame.hpp"
#include "map/ring_spikes.hpp"
#include "map/simplify_map.hpp"
#include "map/stroke_cover.hpp"
#include "map/unique_segments.hpp"

namespace casteljau {

namespace {

using map_detail::kDensifyDegrees;

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

// Whether some step of the ring or line goes more than half way round (split_ring_at_antimeridian
// then cuts it).
bool crosses_antimeridian(std::span<const Point> r) {
    for (std::size_t i = 1; i < r.size(); ++i)
        if (std::fabs(r[i].x - r[i - 1].x) > 180) return true;
    return false;
}

class Projector {
public:
    explicit Projector(const MapProjection& p) : proj_(p), densify_(!p.preserves_graticule_lines()) {}

    // Projects a lon/lat polyline into `out` (points that cannot be projected are dropped).
    void project(std::span<const Point> in, bool closed, std::vector<Point>& out) const {
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
                if (!crosses_antimeridian(r)) {
                    // What split_ring_at_antimeridian gives such a ring, without its copies: the
                    // ring less its repeated closing position.
                    if (r.size() < 3) continue;
                    if (r.front() == r.back()) r = r.first(r.size() - 1);
                    ring_piece(r, exterior, v);
                    continue;
                }
                pieces_.clear();
                split_ring_at_antimeridian(r, pieces_);
                for (const auto& piece : pieces_) ring_piece(piece, exterior, v);
            }
        }
    }

private:
    // One piece of a ring: oriented (exteriors counter-clockwise in lon/lat, positive area; holes
    // clockwise), projected, handed to the visitor.
    void ring_piece(std::span<const Point> r, bool exterior, PieceVisitor& v) const {
        const double a = ring_area2(r);
        if ((exterior && a < 0) || (!exterior && a > 0)) {
            reversed_.assign(r.rbegin(), r.rend());
            r = reversed_;
        }
        project(r, true, projected_);
        if (projected_.size() >= 3) v.ring(projected_);
    }

    const MapProjection& proj_;
    bool densify_;
    mutable std::vector<std::vector<Point>> pieces_;
    mutable std::vector<Point> reversed_;
    mutable std::vector<Point> projected_;
};

struct BoundsVisitor final : PieceVisitor {
    Rect r{INFINITY, INFINITY, -INFINITY, -INFINITY};
    void add(Point p) {
        r.x0 = std::min(r.x0, p.x);
        r.y0 = std::min(r.y0, p.y);
        r.x1 = std::max(r.x1, p.x);
        r.y1 = std::max(r.y1, p.y);
    }
    void ring(const std::vector<Point>& pts) override {
        for (const Point& p : pts) add(p);
    }
    void line(const std::vector<Point>& pts) override {
        for (const Point& p : pts) add(p);
    }
    void point(Point p) override { add(p); }
};

// Appends the segments of the polyline `pts` to `out`, and for a closed one (`closed`) the segment
// back to its start; a single point gives none.
void append_polyline_segments(std::span<const Point> pts, bool closed, std::vector<LineSegment>& out) {
    if (pts.size() < 2) return;
    for (std::size_t i = 1; i < pts.size(); ++i) out.push_back({pts[i - 1], pts[i]});
    if (closed) out.push_back({pts.back(), pts.front()});
}

// Appends the segments of `path` (pixel space; curves flattened within `tolerance`) to `out`: its
// closed contours with their closing segments, and a contour of one point as nothing, as stroke()
// draws them.
void append_segments(const Path& path, double tolerance, Polyline& flat, std::vector<LineSegment>& out) {
    if (path.empty()) return;
    flat.clear();
    flatten(path, Affine{}, tolerance, flat);
    std::size_t begin = 0;
    for (std::size_t c = 0; c < flat.contour_ends.size(); ++c) {
        const std::size_t end = flat.contour_ends[c];
        append_polyline_segments(std::span<const Point>(flat.points).subspan(begin, end - begin), flat.closed[c], out);
        begin = end;
    }
}

// Builds the pixel-space paths of one feature.
struct PathVisitor final : PieceVisitor {
    Affine m;
    double point_radius = 3;
    // Strokes only: rings and lines cut to this rectangle around the image (clip_to_frame.hpp).
    std::optional<Rect> clip;
    bool fill_only = false;              // rings only filled: their spikes go (ring_spikes.hpp)
    Path fill;                           // polygons + point disks
    Path lines;                          // open polylines, to be stroked
    std::vector<Point> mapped, clipped;  // a ring in pixel space
    // A fill's visitor that also gathers the segments a sampled stroke draws of the rings and point
    // disks (append_segments), so that the feature is projected once for both: the rings as the
    // stroke's visitor would add them (spikes kept, cut to stroke_clip, as lines are too), the
    // disks flattened within disk_tolerance. nullptr: none.
    std::vector<LineSegment>* ring_segments = nullptr;
    std::optional<Rect> stroke_clip;
    double disk_tolerance = 0;
    Polyline flat;
    void ring(const std::vector<Point>& pts) override {
        mapped.resize(pts.size());
        for (std::size_t i = 0; i < pts.size(); ++i) mapped[i] = m.apply(pts[i]);
        if (ring_segments) {
            if (!stroke_clip || map_detail::inside(mapped, *stroke_clip)) {
                append_polyline_segments(mapped, true, *ring_segments);
            } else {
                map_detail::clip_ring(mapped, *stroke_clip, clipped);
                if (clipped.size() >= 3) append_polyline_segments(clipped, true, *ring_segments);
            }
        }
        if (fill_only) {
            map_detail::drop_spikes(mapped);
            if (mapped.size() < 3) return;
        }
        if (clip && !map_detail::inside(mapped, *clip)) {
            map_detail::clip_ring(mapped, *clip, clipped);
            if (clipped.size() >= 3) fill.add_polygon(clipped);
            return;
        }
        fill.add_polygon(mapped);
    }
    void line(const std::vector<Point>& pts) override {
        mapped.resize(pts.size());
        for (std::size_t i = 0; i < pts.size(); ++i) mapped[i] = m.apply(pts[i]);
        const std::optional<Rect>& cut = clip ? clip : stroke_clip;
        if (cut && !map_detail::inside(mapped, *cut)) {
            map_detail::clip_line(mapped, *cut, lines);
            return;
        }
        lines.move_to(mapped[0]);
        for (std::size_t i = 1; i < mapped.size(); ++i) lines.line_to(mapped[i]);
    }
    void point(Point p) override {
        if (!(point_radius > 0)) return;
        fill.add_circle(m.apply(p), point_radius);
        if (ring_segments) {
            Path disk;
            disk.add_circle(m.apply(p), point_radius);
            append_segments(disk, disk_tolerance, flat, *ring_segments);
        }
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
        if (!std::isfinite(b.x0) || !std::isfinite(b.x1) || !std::isfinite(b.y0) || !std::isfinite(b.y1) ||
            !(b.x0 < b.x1) || !(b.y0 < b.y1) || b.y0 < -90 || b.y1 > 90 || b.x0 < -540 || b.x1 > 540)
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
            throw Error(ErrorKind::InvalidData,
                        "the map has no geometry to draw (pass --bbox to draw an empty extent)");
        ext = b.r;
    }
    double ew = ext.width(), eh = ext.height();
    if (ew <= 0 && eh <= 0) {  // a single point: a unit extent around it
        ew = eh = 1;
        ext = Rect{ext.x0 - 0.5, ext.y0 - 0.5, ext.x0 + 0.5, ext.y0 + 0.5};
    } else if (ew <= 0) {
        ext.x0 -= eh / 2;
        ext.x1 += eh / 2;
        ew = eh;
    } else if (eh <= 0) {
        ext.y0 -= ew / 2;
        ext.y1 += ew / 2;
        eh = ew;
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

namespace {

// Features are projected and drawn in chunks of about this many input positions, so that only one
// chunk's pixel-space paths exist at a time.
constexpr std::size_t kChunkPositions = std::size_t(1) << 20;

// Horizontal bands of the image, each drawn by one thread at a time. How the image is cut depends
// only on its height, never on the number of threads, so the pixels are the same for any thread
// count (the rasterizer works relative to its clip's origin, so a different cut could round a
// coverage differently).
std::vector<IRect> bands_of(int width, int height) {
    const int n = std::clamp((height + 255) / 256, 1, 16);
    std::vector<IRect> bands;
    for (int i = 0; i < n; ++i) {
        const int y0 = static_cast<int>(static_cast<long long>(height) * i / n);
        const int y1 = static_cast<int>(static_cast<long long>(height) * (i + 1) / n);
        if (y1 > y0) bands.push_back(IRect{0, y0, width, y1});
    }
    return bands;
}

bool overlaps(const Rect& r, const IRect& band) { return r.y1 >= band.y0 && r.y0 <= band.y1; }

// Strokes at most this wide (pixels) with round joins and caps are drawn by round_stroke_mask,
// whose cost grows with the pixels they cover; wider ones by their outline, whose cost grows with
// its boundary while the capsules' would grow with their area.
constexpr double kThinStrokeWidth = 2;

bool thin_round(const StrokeStyle& ss) {
    return ss.join == LineJoin::Round && ss.cap == LineCap::Round && ss.width <= kThinStrokeWidth;
}

// One feature made ready to draw: its pixel-space fill (or stroke outline) and colour.
struct Drawable {
    Path path;
    Color color;
    Path rings;  // strokes: polygon rings still to be stroked, after SharedBorders
    // Fills: the control bounds of path, and the rasterizer's verdict on it, decided once for the
    // whole image rather than by every band the feature reaches (decide_topology).
    Rect box{};
    Topology topology = Topology::Unknown;
};

}  // namespace

int map_threads(int requested) {
    if (requested < 0 || requested > 256)
        throw Error(ErrorKind::InvalidArgument, "threads must be 0 (all cores) to 256");
    const int pool = parallel::thread_count();
    return requested > 0 ? std::min(requested, pool) : pool;
}

namespace {

// Starts `sc` over `region`, making it first when needed: writing into `*into` itself when given
// (SeamlessCompositor::reset_into), else with a layer of its own.
void start_compositor(std::optional<SeamlessCompositor>& sc, const IRect& region, Pixmap* into) {
    if (!sc && into)
        sc.emplace(*into, region);
    else if (!sc)
        sc.emplace(region);
    else if (into)
        sc->reset_into(*into, region);
    else
        sc->reset(region);
}

// How far outside its positions' bounds a feature may draw: the longest reach of a stroke (a miter
// or a square cap) and a point's disk, plus a pixel of anti-aliasing.
double draw_reach(const MapStyle& style) {
    double reach = 0;
    for (const MapLayerStyle& l : style.layers)
        reach = std::max(reach, 0.5 * l.stroke_width * std::max({style.miter_limit, std::sqrt(2.0), 1.0}));
    return reach + std::max(style.point_radius, 0.0) + 1;
}

// Whether projected bounds `b` reach the frame's image, `reach` pixels around it.
bool reaches_image(const Rect& b, const MapFrame& frame, double reach) {
    if (!(b.x0 <= b.x1) || !(b.y0 <= b.y1)) return false;  // nothing projected
    if (!std::isfinite(b.x0) || !std::isfinite(b.x1) || !std::isfinite(b.y0) || !std::isfinite(b.y1)) return true;
    Rect r{INFINITY, INFINITY, -INFINITY, -INFINITY};
    for (Point c : {Point{b.x0, b.y0}, Point{b.x1, b.y0}, Point{b.x0, b.y1}, Point{b.x1, b.y1}}) {
        const Point p = frame.to_pixel.apply(c);
        r = Rect{std::min(r.x0, p.x), std::min(r.y0, p.y), std::max(r.x1, p.x), std::max(r.y1, p.y)};
    }
    return r.x1 >= -reach && r.y1 >= -reach && r.x0 <= frame.width + reach && r.y0 <= frame.height + reach;
}

// render_map onto `target`; `cleared`: the target is known to be transparent already (a new
// Pixmap), so a transparent background need not be written. `simplified`: the geometry to draw
// in place of the data's (nullptr: the data's, simplified here when opts.simplify asks).
void draw_map(const MapData& data, const map_detail::SimplifiedMap* simplified, const MapProjection& proj,
              const MapFrame& frame, const MapStyle& style, const MapOptions& opts, Pixmap& target, bool cleared) {
    if (target.width() != frame.width || target.height() != frame.height)
        throw Error(ErrorKind::InvalidArgument, "render_map: the pixmap does not have the frame's size");
    if (!(opts.simplify >= 0) || !std::isfinite(opts.simplify))
        throw Error(ErrorKind::InvalidArgument, "simplify must be a finite number of pixels >= 0");
    const int threads = map_threads(opts.threads);
    // The geometry at the image's resolution, unless the caller brings it (or asks for none), made
    // when the first layer draws something.
    std::optional<map_detail::SimplifiedMap> own;
    // Sparse data are drawn as they are (map_detail::worth_simplifying), with their features'
    // bounds for leaving out what cannot reach the image.
    auto simplify_once = [&] {
        if (simplified || !(opts.simplify > 0)) return;
        if (map_detail::worth_simplifying(data, proj, frame.to_pixel))
            own = map_detail::simplify_map(data, map_detail::find_border_nodes(data), proj, frame.to_pixel,
                                           opts.simplify, threads);
        else
            own = map_detail::bounds_only(data, proj, threads);
        simplified = &*own;
    };
    auto geometries = [&](std::size_t i) -> const std::vector<Geometry>& {
        return simplified && !simplified->features.empty() ? simplified->features[i] : data.features[i].geometries;
    };
    // Features that cannot reach the image are not drawn (their bounds are known only with the
    // simplified copy; a projection that bends segments may draw outside its positions' bounds).
    const double reach = draw_reach(style);
    // Outlines are cut a little farther out than anything reaches (clip_to_frame.hpp).
    const Rect stroke_clip{-2 * reach, -2 * reach, frame.width + 2 * reach, frame.height + 2 * reach};
    auto visible = [&](std::size_t i) {
        return !simplified || !proj.preserves_graticule_lines() || reaches_image(simplified->bounds[i], frame, reach);
    };
    FillOptions fo;
    fo.rule = opts.fill_rule;
    fo.tolerance = opts.tolerance;
    fo.exact_overlaps = opts.exact_overlaps;
    FillOptions outline_fo = fo;
    outline_fo.rule = FillRule::NonZero;
    outline_fo.exact_overlaps = true;  // a shared border's two copies must not add up
    StrokeStyle ss;
    ss.join = style.join;
    ss.cap = style.cap;
    ss.miter_limit = style.miter_limit;
    const std::vector<IRect> bands = bands_of(frame.width, frame.height);

    // Per worker: a projection of its own (PROJ objects are not shared), a projector, a canvas.
    std::vector<MapProjection> projections;
    std::vector<std::unique_ptr<Projector>> projectors;
    std::vector<std::unique_ptr<Canvas>> canvases;
    for (int w = 0; w < threads; ++w) projections.push_back(w == 0 ? proj.clone() : projections[0].clone());
    for (int w = 0; w < threads; ++w) {
        projectors.push_back(std::make_unique<Projector>(projections[static_cast<std::size_t>(w)]));
        canvases.push_back(std::make_unique<Canvas>(target));
        canvases.back()->fill_options() = fo;
    }
    // The background, band by band on the workers. A new pixmap is transparent zero pages: a
    // transparent background leaves them to be mapped where the fills composite (on the workers
    // too), and never where nothing is drawn.
    // While nothing is drawn on it, such a pixmap takes a seamless layer's fills directly
    // (SeamlessCompositor::reset_into): the same pixels, without a layer.
    // Any other background waits for the first drawing: a seamless fill's compositors set each
    // row to it as they composite onto it, while the row is in cache (the same pixels as filling
    // the image first); anything else paints it first (paint_background).
    // A drawn pixmap under a transparent background is cleared first, band by band on the
    // workers, and then takes the fills directly as a new one does.
    if (!cleared && style.background.a == 0) {
        parallel::for_each_index(threads, bands.size(), [&](int, std::size_t b) {
            target.fill_rows(bands[b].y0, bands[b].y1, style.background);
        });
        cleared = true;
    }
    bool target_clear = cleared && style.background.a == 0;
    std::vector<char> background_due(bands.size(), !target_clear);
    auto paint_background = [&] {
        parallel::for_each_index(threads, bands.size(), [&](int, std::size_t b) {
            if (background_due[b]) target.fill_rows(bands[b].y0, bands[b].y1, style.background);
            background_due[b] = 0;
        });
    };
    std::optional<SeamlessCompositor> whole;  // the whole image
    std::vector<std::optional<SeamlessCompositor>> band_compositors(
        static_cast<std::size_t>(threads));  // one band per worker

    auto build = [&](int w, std::size_t feature, PathVisitor& v) {
        v.m = frame.to_pixel;
        v.point_radius = style.point_radius;
        std::size_t n = 0, rings = 0;
        for (const Geometry& g : geometries(feature)) {
            n += g.points.size();
            rings += g.ring_ends.size();
        }
        // A closed ring is its positions plus a close (the projector may add points: a hint).
        if (n > 0) v.fill.reserve(n + rings, n + 2 * rings);
        for (const Geometry& g : geometries(feature)) projectors[static_cast<std::size_t>(w)]->geometry(g, v);
    };
    auto positions_of = [&](std::size_t feature) {
        std::size_t n = 0;
        for (const Geometry& g : geometries(feature)) n += g.points.size();
        return n;
    };
    // Calls make(worker, feature, out) for the features in `order`, a chunk at a time built in
    // parallel, then draw(chunk) with the chunk's drawables in the same order.
    auto chunked = [&](const std::vector<std::size_t>& order, auto&& make, auto&& draw) {
        std::vector<std::optional<Drawable>> chunk;
        for (std::size_t begin = 0; begin < order.size();) {
            std::size_t end = begin, positions = 0;
            while (end < order.size() && (end == begin || positions < kChunkPositions))
                positions += positions_of(order[end++]);
            chunk.assign(end - begin, std::nullopt);
            parallel::for_each_index(threads, end - begin,
                                     [&](int w, std::size_t i) { make(w, order[begin + i], chunk[i]); });
            draw(chunk);
            begin = end;
        }
    };

    for (const MapLayerStyle& layer : style.layers) {
        if (layer.fill || ((layer.stroke || layer.fill) && layer.stroke_width > 0)) simplify_once();
        std::vector<std::size_t> order;
        for (std::size_t i = 0; i < data.features.size(); ++i)
            if (layer.filter.matches(data.features[i]) && visible(i)) order.push_back(i);
        const std::optional<Color> line_color = layer.stroke ? layer.stroke : layer.fill;
        ss.width = layer.stroke_width;
        const bool sampled = line_color && layer.stroke_width > 0 && opts.sampled_strokes && thin_round(ss);
        // A sampled stroke after a fill takes its segments from the fill's visitors (one per
        // feature of `order`, in its order), so that every feature is projected once.
        const bool stroke_with_fill = sampled && layer.fill;
        std::vector<std::vector<LineSegment>> feature_segments(stroke_with_fill ? order.size() : 0);
        std::vector<std::uint32_t> segment_slot(stroke_with_fill ? data.features.size() : 0);
        for (std::size_t k = 0; k < feature_segments.size(); ++k)
            segment_slot[order[k]] = static_cast<std::uint32_t>(k);
        // The stroke's segments the fills' visitors gathered, one copy of each, in feature order.
        auto gathered_segments = [&] {
            std::vector<LineSegment> segments;
            std::size_t total = 0;
            for (const auto& f : feature_segments) total += f.size();
            segments.reserve(total);
            for (auto& f : feature_segments) {
                segments.insert(segments.end(), f.begin(), f.end());
                std::vector<LineSegment>().swap(f);
            }
            map_detail::drop_repeated_segments(segments);
            return segments;
        };
        // A sampled stroke's sweeps: each reads every segment once to find those it needs, so one
        // thread sweeps the whole image at once and several take a band each.
        const std::vector<IRect> sweeps =
            threads == 1 ? std::vector<IRect>{IRect{0, 0, frame.width, frame.height}} : bands;
        // An opaque sampled stroke over a seamless fill is swept first (stroke_cover.hpp).
        map_detail::StrokeCover cover;
        bool covered = false;
        // Fills: seamless (SeamlessCompositor, last feature first so that later features win) or source-over in order.
        auto make_fill = [&](int w, std::size_t feature, std::optional<Drawable>& out) {
            const std::optional<Color> c = layer.fill_for(data.features[feature]);
            if (!c && !stroke_with_fill) return;
            PathVisitor v;
            v.fill_only = true;
            std::vector<LineSegment> ring_segments;
            if (stroke_with_fill) {
                v.stroke_clip = stroke_clip;
                if (layer.stroke) v.ring_segments = &ring_segments;  // a fill colour strokes lines only
                v.disk_tolerance = opts.tolerance;
            }
            build(w, feature, v);
            if (stroke_with_fill) {
                std::vector<LineSegment>& mine = feature_segments[segment_slot[feature]];
                append_segments(v.lines, opts.tolerance, v.flat, mine);
                mine.insert(mine.end(), ring_segments.begin(), ring_segments.end());
            }
            if (!c || v.fill.empty()) return;
            out = Drawable{std::move(v.fill), *c, Path{}};
            out->box = out->path.control_bounds();
            if (fo.exact_overlaps) {
                const Rect& b = out->box;
                const double bw = std::min(b.x1, double(frame.width)) - std::max(b.x0, 0.0);
                const double bh = std::min(b.y1, double(frame.height)) - std::max(b.y0, 0.0);
                if (bw > 0 && bh > 0) out->topology = decide_topology(out->path, Affine{}, fo.tolerance, bw, bh);
            }
        };
        auto fill_options = [&](const Drawable& d) {
            FillOptions o = fo;
            o.topology = d.topology;
            if (covered) o.hidden = &cover.full();
            return o;
        };
        const bool seamless = layer.fill && opts.seamless;
        if (!seamless) paint_background();
        if (seamless) {
            std::reverse(order.begin(), order.end());
            std::size_t positions = 0;
            for (std::size_t i : order) positions += positions_of(i);
            // A layer that fits in one chunk is composited band by band, each band in a compositor
            // of its size that the worker reuses (5 bytes per pixel of one band per thread, not of
            // the image). Several chunks add up in one compositor of the whole image instead,
            // composited once at the end.
            const bool banded = positions <= kChunkPositions;
            Pixmap* const direct = target_clear ? &target : nullptr;  // the fills go straight into it
            if (!banded) start_compositor(whole, IRect{0, 0, frame.width, frame.height}, direct);
            // One chunk holds every feature, so the stroke's segments are all known before any
            // fill is drawn.
            const bool occlude =
                stroke_with_fill && banded && fo.exact_overlaps && line_color->a == 255 && layer.opacity >= 1;
            bool drew = false;
            chunked(order, make_fill, [&](const std::vector<std::optional<Drawable>>& chunk) {
                if (occlude) {
                    cover.sweep(gathered_segments(), 0.5 * ss.width, IRect{0, 0, frame.width, frame.height}, sweeps,
                                threads);
                    covered = true;
                }
                parallel::for_each_index(threads, bands.size(), [&](int w, std::size_t b) {
                    Rasterizer& raster = canvases[static_cast<std::size_t>(w)]->rasterizer();
                    SeamlessCompositor* into = banded ? nullptr : &*whole;
                    for (const auto& d : chunk) {
                        if (!d || !overlaps(d->box, bands[b])) continue;
                        if (!into) {
                            std::optional<SeamlessCompositor>& band = band_compositors[static_cast<std::size_t>(w)];
                            start_compositor(band, bands[b], direct);
                            into = &*band;
                        }
                        into->add(raster, d->path, fill_options(*d), d->color, layer.opacity, bands[b]);
                    }
                    if (banded && into) {
                        if (background_due[b])
                            into->composite_onto(target, style.background);
                        else
                            into->composite_onto(target);
                        background_due[b] = 0;
                    }
                });
                for (const auto& d : chunk) drew = drew || d.has_value();
            });
            if (!banded && drew) {
                if (background_due[0]) {  // every band is due, or none
                    whole->composite_onto(target, style.background);
                    std::fill(background_due.begin(), background_due.end(), 0);
                } else {
                    whole->composite_onto(target);
                }
            }
            paint_background();  // the bands no fill reached
            target_clear = target_clear && !drew;
            std::reverse(order.begin(), order.end());
        } else if (layer.fill) {
            chunked(order, make_fill, [&](const std::vector<std::optional<Drawable>>& chunk) {
                parallel::for_each_index(threads, bands.size(), [&](int w, std::size_t b) {
                    Canvas& canvas = *canvases[static_cast<std::size_t>(w)];
                    canvas.save();
                    canvas.clip_rect(Rect{0.0, double(bands[b].y0), double(bands[b].x1), double(bands[b].y1)});
                    for (const auto& d : chunk) {
                        if (!d || !overlaps(d->box, bands[b])) continue;
                        Paint paint = Paint::solid(d->color);
                        paint.opacity = layer.opacity;
                        canvas.fill_path(d->path, paint, fill_options(*d));
                    }
                    canvas.restore();
                });
            });
            target_clear = false;
        }
        // Strokes: the outlines of every feature in one path per colour, filled once with the
        // nonzero rule. Polygon rings go through SharedBorders first, in feature order, so a border
        // shared by two features is stroked once (the union, and so the pixels, stay the same; the
        // exact overlap computation along every border is saved).
        if (!line_color || !(layer.stroke_width > 0)) continue;
        if (sampled) {
            // The union of every feature's capsules, drawn from the segments directly
            // (round_stroke.hpp): no outline, so nothing folds. The union does not depend on
            // repeats, so a shared border's second copy is dropped before the sweep.
            Paint paint = Paint::solid(*line_color);
            paint.opacity = layer.opacity;
            if (covered) {
                target_clear = false;
                parallel::for_each_index(threads, sweeps.size(), [&](int w, std::size_t k) {
                    Canvas& canvas = *canvases[static_cast<std::size_t>(w)];
                    canvas.save();
                    canvas.clip_rect(
                        Rect{double(sweeps[k].x0), double(sweeps[k].y0), double(sweeps[k].x1), double(sweeps[k].y1)});
                    cover.composite(k, canvas, paint);
                    canvas.restore();
                });
                continue;
            }
            std::vector<LineSegment> segments;
            if (stroke_with_fill) segments = gathered_segments();
            auto make_lines = [&](int w, std::size_t feature, std::optional<Drawable>& out) {
                PathVisitor v;
                v.clip = stroke_clip;
                build(w, feature, v);
                if (!layer.stroke) v.fill.clear();  // a fill colour strokes lines only
                if (!v.lines.empty() || !v.fill.empty())
                    out = Drawable{std::move(v.lines), *line_color, std::move(v.fill)};
            };
            Polyline flat;
            if (!stroke_with_fill)
                chunked(order, make_lines, [&](std::vector<std::optional<Drawable>>& chunk) {
                    for (const auto& d : chunk) {
                        if (!d) continue;
                        append_segments(d->path, opts.tolerance, flat, segments);
                        append_segments(d->rings, opts.tolerance, flat, segments);
                    }
                });
            if (!stroke_with_fill) map_detail::drop_repeated_segments(segments);
            if (segments.empty()) continue;
            target_clear = false;
            parallel::for_each_index(threads, sweeps.size(), [&](int w, std::size_t k) {
                Canvas& canvas = *canvases[static_cast<std::size_t>(w)];
                canvas.save();
                canvas.clip_rect(
                    Rect{double(sweeps[k].x0), double(sweeps[k].y0), double(sweeps[k].x1), double(sweeps[k].y1)});
                canvas.fill_round_stroke(segments, 0.5 * ss.width, paint);
                canvas.restore();
            });
            continue;
        }
        StrokeStyle chain_style = ss;
        chain_style.cap = LineCap::Butt;  // chain ends lie on segments or joins drawn by another chain
        Path outline;
        SharedBorders borders;
        const double merge_distance = stroke_merge_distance(Affine{}, opts.tolerance);
        auto flush = [&] {
            if (outline.empty()) return;
            target_clear = false;
            const Rect box = outline.control_bounds();
            Paint paint = Paint::solid(*line_color);
            paint.opacity = layer.opacity;
            parallel::for_each_index(threads, bands.size(), [&](int w, std::size_t b) {
                if (!overlaps(box, bands[b])) return;
                Canvas& canvas = *canvases[static_cast<std::size_t>(w)];
                canvas.save();
                canvas.clip_rect(Rect{0.0, double(bands[b].y0), double(bands[b].x1), double(bands[b].y1)});
                canvas.fill_options() = outline_fo;
                canvas.fill_path(outline, paint, FillRule::NonZero);
                canvas.fill_options() = fo;
                canvas.restore();
            });
            outline.clear();
            borders.clear();  // bounds its memory; a border split by a flush is drawn twice
        };
        auto make_outline = [&](int w, std::size_t feature, std::optional<Drawable>& out) {
            PathVisitor v;
            v.clip = stroke_clip;
            build(w, feature, v);
            Path o;
            // Lines are always stroked; polygon outlines (point disks too) take the stroke colour.
            if (!v.lines.empty()) o = stroke(v.lines, ss, Affine{}, opts.tolerance);
            Path rings;
            if (layer.stroke && !v.fill.empty()) rings = std::move(v.fill);
            if (!o.empty() || !rings.empty()) out = Drawable{std::move(o), *line_color, std::move(rings)};
        };
        std::vector<Path> chains, whole;
        chunked(order, make_outline, [&](std::vector<std::optional<Drawable>>& chunk) {
            // What is left of each feature's rings, in feature order, then stroked in parallel.
            chains.assign(chunk.size(), Path{});
            whole.assign(chunk.size(), Path{});
            for (std::size_t i = 0; i < chunk.size(); ++i)
                if (chunk[i] && !chunk[i]->rings.empty())
                    borders.add(chunk[i]->rings, chains[i], whole[i], merge_distance);
            parallel::for_each_index(threads, chunk.size(), [&](int, std::size_t i) {
                if (!chains[i].empty()) chunk[i]->path.append(stroke(chains[i], chain_style, Affine{}, opts.tolerance));
                if (!whole[i].empty()) chunk[i]->path.append(stroke(whole[i], ss, Affine{}, opts.tolerance));
            });
            for (const auto& d : chunk) {
                if (!d) continue;
                if (outline.points().size() + d->path.points().size() > limits::kMaxPathPoints / 2) flush();
                outline.append(d->path);
            }
        });
        flush();
    }
    paint_background();
}

}  // namespace

void render_map(const MapData& data, const MapProjection& proj, const MapFrame& frame, const MapStyle& style,
                const MapOptions& opts, Pixmap& target) {
    draw_map(data, nullptr, proj, frame, style, opts, target, false);
}

namespace map_detail {

void render_simplified_map(const MapData& data, const SimplifiedMap& simplified, const MapProjection& proj,
                           const MapFrame& frame, const MapStyle& style, const MapOptions& opts, Pixmap& target) {
    draw_map(data, &simplified, proj, frame, style, opts, target, false);
}

}  // namespace map_detail

Pixmap render_map(const MapData& data, const MapProjection& proj, const MapStyle& style, const MapOptions& opts) {
    const MapFrame fr = fit_map(data, proj, opts);
    Pixmap pm(fr.width, fr.height);
    draw_map(data, nullptr, proj, fr, style, opts, pm, true);
    return pm;
}

}  // namespace casteljau
