// Map stage: drawing a map's features onto a pixmap, layer by layer (see draw_map.hpp).
//
// A layer fills its features (seamless, or source-over in order), then strokes their outlines:
// round strokes up to 64 px wide as the union of one capsule per segment (round_stroke.hpp), wider
// or other strokes through their outlines, with a border two features share stroked once.
#include "map/draw_map.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "casteljau/canvas.hpp"
#include "casteljau/error.hpp"
#include "casteljau/limits.hpp"
#include "casteljau/round_stroke.hpp"
#include "casteljau/seamless.hpp"
#include "core/for_each_index.hpp"
#include "map/feature_paths.hpp"
#include "map/stroke_cover.hpp"
#include "map/unique_segments.hpp"

namespace casteljau::map_detail {

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

// Strokes at most this wide (pixels) with round joins and caps are drawn by round_stroke_mask, as
// the union of their capsules: its cost grows with the capsules' sample lines (their height plus
// the width, 32 lines a pixel), while an outline's grows with how often it folds inside a pixel
// and with the exact cells of its overlaps, which wide strokes over dense borders multiply (Natural
// Earth 10m, 1024 px wide, single thread: 3 px 2.6 s and 345 MB through outlines, 0.16 s and 85 MB
// sampled; 48 px at 4096 px wide 21 s against 1.2 s). Wider strokes keep their outline, whose cost
// does not grow with the width.
constexpr double kMaxSampledStrokeWidth = 64;

// Whether the outline of `path` stroked `width` wide piles up: its points lie closer together, on
// average, than half the width, so that the outline's pieces crowd the pixels and the overlap check
// would recompute many of them exactly. Only such strokes collect their interior capsules
// (stroke_interior): elsewhere the capsules find few cells and cost as much memory as the outline.
bool crowded(const Path& path, double width) {
    const auto pts = path.points();
    if (pts.size() < 2) return false;
    double length = 0;
    for (std::size_t i = 1; i < pts.size(); ++i) length += distance(pts[i - 1], pts[i]);
    return length < 0.5 * width * static_cast<double>(pts.size() - 1);
}

bool sampled_round(const StrokeStyle& ss) {
    return ss.join == LineJoin::Round && ss.cap == LineCap::Round && ss.width <= kMaxSampledStrokeWidth;
}

// One feature made ready to draw: its pixel-space fill (or stroke outline) and colour.
struct Drawable {
    Path path;
    Color color;
    Path rings;  // strokes: polygon rings still to be stroked, after SharedBorders
    // Strokes: capsules (pixel space) inside the stroke of the lines in path, and inside the whole
    // stroke of the rings.
    std::vector<CutCapsule> inside{}, ring_inside{};
    // Fills: the control bounds of path, and the rasterizer's verdict on it, decided once for the
    // whole image rather than by every band the feature reaches: from the kept overlap analysis
    // (fill_analyses.hpp), whose boxes confine the overlap check to the pixels near the segments
    // that need it, or else by decide_topology.
    Rect box{};
    Topology topology = Topology::Unknown;
    std::vector<Rect> overlap_boxes{};
};
using Chunk = std::vector<std::optional<Drawable>>;

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
    const Rect r = frame.to_pixel.map_bounds(b);
    return r.x1 >= -reach && r.y1 >= -reach && r.x0 <= frame.width + reach && r.y0 <= frame.height + reach;
}

Rect to_rect(const IRect& r) { return Rect{double(r.x0), double(r.y0), double(r.x1), double(r.y1)}; }

// What one layer draws: the features its filter keeps, and the segments of a sampled stroke that
// its fill's visitors gather (one list per feature of `order`, in its order), so that every
// feature is projected once.
struct LayerWork {
    explicit LayerWork(const MapLayerStyle& l) : layer(l) {}

    const MapLayerStyle& layer;
    std::vector<std::size_t> order;
    std::optional<Color> line_color;  // the stroke's, or the fill's for lines without a stroke colour
    bool sampled = false;             // a round stroke drawn as a union of capsules
    bool stroke_with_fill = false;    // sampled, with segments from the fill's visitors
    std::vector<std::vector<LineSegment>> feature_segments;
    std::vector<std::uint32_t> segment_slot;  // per feature of the data: its list
    // An opaque sampled stroke over a seamless fill, swept before the fill (stroke_cover.hpp).
    StrokeCover cover;
    bool covered = false;

    // The segments the fills' visitors gathered, one copy of each, in feature order (the lists
    // are freed).
    std::vector<LineSegment> gathered_segments() {
        std::vector<LineSegment> segments;
        std::size_t total = 0;
        for (const auto& f : feature_segments) total += f.size();
        segments.reserve(total);
        for (auto& f : feature_segments) {
            segments.insert(segments.end(), f.begin(), f.end());
            std::vector<LineSegment>().swap(f);
        }
        drop_repeated_segments(segments);
        return segments;
    }
};

class MapDrawing {
public:
    MapDrawing(const MapData& data, const SimplifiedMap* simplified, const MapProjection& proj, const MapFrame& frame,
               const MapStyle& style, const MapOptions& opts, Pixmap& target, bool cleared, KeptMap* cache);

    void draw() {
        for (const MapLayerStyle& layer : style_.layers) draw_layer(layer);
        paint_background();
    }

private:
    // The geometry at the image's resolution, unless the caller brought it (or asks for none).
    void simplify_once();
    const std::vector<Geometry>& geometries(std::size_t i) const {
        return simplified_ && !simplified_->features.empty() ? simplified_->features[i] : data_.features[i].geometries;
    }
    // Features that cannot reach the image are not drawn (their bounds are known only with the
    // simplified copy; a projection that bends segments may draw outside its positions' bounds).
    bool visible(std::size_t i) const {
        return !simplified_ || !proj_.preserves_graticule_lines() ||
               reaches_image(simplified_->bounds[i], frame_, reach_);
    }
    std::size_t positions_of(std::size_t feature) const {
        std::size_t n = 0;
        for (const Geometry& g : geometries(feature)) n += g.points.size();
        return n;
    }
    void build(int w, std::size_t feature, PathVisitor& v) const;
    // Feature `feature`'s overlap analysis in this frame: the cache's, found and kept by the first
    // render that fills it; nullopt without a cache.
    std::optional<OverlapRegion> overlap_region(std::size_t feature, const Path& path) const;
    // Calls make(worker, feature, out) for the features in `order`, a chunk at a time built in
    // parallel, then draw(chunk) with the chunk's drawables in the same order.
    template <class Make, class Draw>
    void chunked(const std::vector<std::size_t>& order, Make&& make, Draw&& draw) const;
    // Calls each(canvas) on every band (or sweep) of `regions`, on the workers, with the
    // worker's canvas clipped to it.
    template <class Each>
    void on_regions(const std::vector<IRect>& regions, Each&& each) const;
    void paint_background();

    void draw_layer(const MapLayerStyle& layer);
    void make_fill(LayerWork& lw, int w, std::size_t feature, std::optional<Drawable>& out) const;
    FillOptions fill_options(const LayerWork& lw, const Drawable& d) const {
        FillOptions o = fo_;
        o.topology = d.topology;
        o.overlap_boxes = d.overlap_boxes;
        if (lw.covered) o.hidden = &lw.cover.full();
        // Seamless fills that need exactness take the per-cell check, not the winding sweep: a
        // coastline folds into short monotone chains, so the sweep's strips cost more than the
        // check's boundary pixels (countries-land-10km at 4096 px: 2 % more instructions).
        o.winding_sweep = !opts_.seamless;
        return o;
    }
    void fill_seamless(LayerWork& lw);
    void fill_in_order(LayerWork& lw);
    void stroke_sampled(LayerWork& lw);
    void stroke_outlines(LayerWork& lw);

    const MapData& data_;
    const SimplifiedMap* simplified_;
    KeptMap* cache_;
    // The cache's analyses of the geometry drawn: the data's own, or those of held_, the cache's
    // copy simplified to this frame's scale.
    FillAnalyses* kept_;
    std::shared_ptr<ScaledMap> held_;
    std::optional<SimplifiedMap> own_;
    const MapProjection& proj_;
    const MapFrame& frame_;
    const MapStyle& style_;
    const MapOptions& opts_;
    Pixmap& target_;
    const int threads_;
    const double reach_;
    const Rect stroke_clip_;  // outlines are cut a little farther out than anything reaches
    FillOptions fo_, outline_fo_;
    StrokeStyle ss_;  // the current layer's
    const std::vector<IRect> bands_;
    // A sampled stroke's sweeps: each reads every segment once to find those it needs, so one
    // thread sweeps the whole image at once and several take a band each.
    std::vector<IRect> sweeps_;
    // Per worker: a projection of its own (PROJ objects are not shared), a projector, a canvas.
    std::vector<MapProjection> projections_;
    std::vector<std::unique_ptr<Projector>> projectors_;
    std::vector<std::unique_ptr<Canvas>> canvases_;
    bool target_clear_ = false;                                        // nothing drawn on a transparent target yet
    std::vector<char> background_due_;                                 // per band
    std::optional<SeamlessCompositor> whole_;                          // the whole image
    std::vector<std::optional<SeamlessCompositor>> band_compositors_;  // one band per worker
};

MapDrawing::MapDrawing(const MapData& data, const SimplifiedMap* simplified, const MapProjection& proj,
                       const MapFrame& frame, const MapStyle& style, const MapOptions& opts, Pixmap& target,
                       bool cleared, KeptMap* cache)
    : data_(data),
      simplified_(simplified),
      cache_(simplified ? nullptr : cache),
      kept_(cache_ ? &cache_->as_is() : nullptr),
      proj_(proj),
      frame_(frame),
      style_(style),
      opts_(opts),
      target_(target),
      threads_(map_threads(opts.threads)),
      reach_(draw_reach(style)),
      stroke_clip_{-2 * reach_, -2 * reach_, frame.width + 2 * reach_, frame.height + 2 * reach_},
      bands_(bands_of(frame.width, frame.height)) {
    fo_.rule = opts.fill_rule;
    fo_.tolerance = opts.tolerance;
    fo_.exact_overlaps = opts.exact_overlaps;
    outline_fo_ = fo_;
    outline_fo_.rule = FillRule::NonZero;
    outline_fo_.exact_overlaps = true;  // a shared border's two copies must not add up
    ss_.join = style.join;
    ss_.cap = style.cap;
    ss_.miter_limit = style.miter_limit;
    sweeps_ = threads_ == 1 ? std::vector<IRect>{IRect{0, 0, frame.width, frame.height}} : bands_;
    for (int w = 0; w < threads_; ++w) projections_.push_back(w == 0 ? proj.clone() : projections_[0].clone());
    for (int w = 0; w < threads_; ++w) {
        projectors_.push_back(std::make_unique<Projector>(projections_[static_cast<std::size_t>(w)]));
        canvases_.push_back(std::make_unique<Canvas>(target));
        canvases_.back()->fill_options() = fo_;
    }
    band_compositors_.resize(static_cast<std::size_t>(threads_));
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
        parallel::for_each_index(threads_, bands_.size(), [&](int, std::size_t b) {
            target.fill_rows(bands_[b].y0, bands_[b].y1, style.background);
        });
        cleared = true;
    }
    target_clear_ = cleared && style.background.a == 0;
    background_due_.assign(bands_.size(), !target_clear_);
}

void MapDrawing::simplify_once() {
    if (simplified_ || !(opts_.simplify > 0)) return;
    // Sparse data are drawn as they are (worth_simplifying), with their features' bounds for
    // leaving out what cannot reach the image. A cache keeps both for the next renders.
    const bool worth = worth_simplifying(data_, proj_, frame_.to_pixel);
    if (cache_ && worth) {
        held_ = cache_->scaled(frame_.to_pixel, opts_.simplify, [&] {
            return simplify_map(data_, cache_->nodes(data_), proj_, frame_.to_pixel, opts_.simplify, threads_);
        });
        simplified_ = &held_->map;
        kept_ = &held_->analyses;
        return;
    }
    if (cache_) {
        simplified_ = &cache_->as_is_bounds(data_, proj_, threads_);
        return;
    }
    if (worth)
        own_ = simplify_map(data_, find_border_nodes(data_), proj_, frame_.to_pixel, opts_.simplify, threads_);
    else
        own_ = bounds_only(data_, proj_, threads_);
    simplified_ = &*own_;
}

void MapDrawing::build(int w, std::size_t feature, PathVisitor& v) const {
    v.m = frame_.to_pixel;
    v.point_radius = style_.point_radius;
    std::size_t n = 0, rings = 0;
    for (const Geometry& g : geometries(feature)) {
        n += g.points.size();
        rings += g.ring_ends.size();
    }
    // A closed ring is its positions plus a close (the projector may add points: a hint).
    if (n > 0) v.fill.reserve(n + rings, n + 2 * rings);
    for (const Geometry& g : geometries(feature)) projectors_[static_cast<std::size_t>(w)]->geometry(g, v);
}

template <class Make, class Draw>
void MapDrawing::chunked(const std::vector<std::size_t>& order, Make&& make, Draw&& draw) const {
    Chunk chunk;
    for (std::size_t begin = 0; begin < order.size();) {
        std::size_t end = begin, positions = 0;
        while (end < order.size() && (end == begin || positions < kChunkPositions))
            positions += positions_of(order[end++]);
        chunk.assign(end - begin, std::nullopt);
        parallel::for_each_index(threads_, end - begin,
                                 [&](int w, std::size_t i) { make(w, order[begin + i], chunk[i]); });
        draw(chunk);
        begin = end;
    }
}

template <class Each>
void MapDrawing::on_regions(const std::vector<IRect>& regions, Each&& each) const {
    parallel::for_each_index(threads_, regions.size(), [&](int w, std::size_t k) {
        Canvas& canvas = *canvases_[static_cast<std::size_t>(w)];
        canvas.save();
        canvas.clip_rect(to_rect(regions[k]));
        each(canvas, k);
        canvas.restore();
    });
}

void MapDrawing::paint_background() {
    parallel::for_each_index(threads_, bands_.size(), [&](int, std::size_t b) {
        if (background_due_[b]) target_.fill_rows(bands_[b].y0, bands_[b].y1, style_.background);
        background_due_[b] = 0;
    });
}

void MapDrawing::draw_layer(const MapLayerStyle& layer) {
    if (layer.fill || ((layer.stroke || layer.fill) && layer.stroke_width > 0)) simplify_once();
    LayerWork lw(layer);
    for (std::size_t i = 0; i < data_.features.size(); ++i)
        if (layer.filter.matches(data_.features[i]) && visible(i)) lw.order.push_back(i);
    lw.line_color = layer.stroke ? layer.stroke : layer.fill;
    ss_.width = layer.stroke_width;
    lw.sampled = lw.line_color && layer.stroke_width > 0 && opts_.sampled_strokes && sampled_round(ss_);
    lw.stroke_with_fill = lw.sampled && layer.fill;
    if (lw.stroke_with_fill) {
        lw.feature_segments.resize(lw.order.size());
        lw.segment_slot.resize(data_.features.size());
        for (std::size_t k = 0; k < lw.order.size(); ++k) lw.segment_slot[lw.order[k]] = static_cast<std::uint32_t>(k);
    }
    if (layer.fill && opts_.seamless) {
        fill_seamless(lw);
    } else {
        paint_background();
        if (layer.fill) fill_in_order(lw);
    }
    if (!lw.line_color || !(layer.stroke_width > 0)) return;
    if (lw.sampled)
        stroke_sampled(lw);
    else
        stroke_outlines(lw);
}

// A fill's drawable (when the feature has a fill colour), and the segments of its sampled stroke.
void MapDrawing::make_fill(LayerWork& lw, int w, std::size_t feature, std::optional<Drawable>& out) const {
    const std::optional<Color> c = lw.layer.fill_for(data_.features[feature]);
    if (!c && !lw.stroke_with_fill) return;
    PathVisitor v;
    v.fill_only = true;
    std::vector<LineSegment> ring_segments;
    if (lw.stroke_with_fill) {
        v.stroke_clip = stroke_clip_;
        if (lw.layer.stroke) v.ring_segments = &ring_segments;  // a fill colour strokes lines only
        v.disk_tolerance = opts_.tolerance;
    }
    build(w, feature, v);
    if (lw.stroke_with_fill) {
        std::vector<LineSegment>& mine = lw.feature_segments[lw.segment_slot[feature]];
        append_segments(v.lines, opts_.tolerance, v.flat, mine);
        mine.insert(mine.end(), ring_segments.begin(), ring_segments.end());
    }
    if (!c || v.fill.empty()) return;
    out = Drawable{std::move(v.fill), *c, Path{}};
    out->box = out->path.control_bounds();
    if (fo_.exact_overlaps) {
        const Rect& b = out->box;
        const double bw = std::min(b.x1, double(frame_.width)) - std::max(b.x0, 0.0);
        const double bh = std::min(b.y1, double(frame_.height)) - std::max(b.y0, 0.0);
        if (bw > 0 && bh > 0) {
            std::optional<OverlapRegion> region = overlap_region(feature, out->path);
            if (region && region->topology != Topology::Unknown) {
                out->topology = region->topology;
                out->overlap_boxes = std::move(region->boxes);
            } else {
                out->topology = decide_topology(out->path, Affine{}, fo_.tolerance, bw, bh);
            }
        }
    }
}

std::optional<OverlapRegion> MapDrawing::overlap_region(std::size_t feature, const Path& path) const {
    FillAnalyses* const k = kept_;
    if (!k) return std::nullopt;
    if (const OverlapRegion* r = k->find(feature)) return FillAnalyses::in_frame(*r, frame_.to_pixel);
    if (k->claim(feature)) return k->keep(feature, path, frame_.to_pixel);
    return std::nullopt;
}

// Seamless fills (SeamlessCompositor), last feature first so that later features win.
void MapDrawing::fill_seamless(LayerWork& lw) {
    std::vector<std::size_t> order(lw.order.rbegin(), lw.order.rend());
    std::size_t positions = 0;
    for (std::size_t i : order) positions += positions_of(i);
    // A layer that fits in one chunk is composited band by band, each band in a compositor of its
    // size that the worker reuses (5 bytes per pixel of one band per thread, not of the image).
    // Several chunks add up in one compositor of the whole image instead, composited once at the
    // end.
    const bool banded = positions <= kChunkPositions;
    Pixmap* const direct = target_clear_ ? &target_ : nullptr;  // the fills go straight into it
    if (!banded) start_compositor(whole_, IRect{0, 0, frame_.width, frame_.height}, direct);
    // One chunk holds every feature, so the stroke's segments are all known before any fill is
    // drawn.
    const bool occlude =
        lw.stroke_with_fill && banded && fo_.exact_overlaps && lw.line_color->a == 255 && lw.layer.opacity >= 1;
    bool drew = false;
    auto make = [&](int w, std::size_t feature, std::optional<Drawable>& out) { make_fill(lw, w, feature, out); };
    chunked(order, make, [&](const Chunk& chunk) {
        // A layer without a stroke colour strokes only its lines: with none, there is no cover
        // and nothing is hidden.
        std::vector<LineSegment> segments;
        if (occlude) segments = lw.gathered_segments();
        if (!segments.empty()) {
            lw.cover.sweep(segments, 0.5 * ss_.width, IRect{0, 0, frame_.width, frame_.height}, sweeps_, threads_);
            lw.covered = true;
        }
        parallel::for_each_index(threads_, bands_.size(), [&](int w, std::size_t b) {
            Rasterizer& raster = canvases_[static_cast<std::size_t>(w)]->rasterizer();
            SeamlessCompositor* into = banded ? nullptr : &*whole_;
            for (const auto& d : chunk) {
                if (!d || !overlaps(d->box, bands_[b])) continue;
                if (!into) {
                    std::optional<SeamlessCompositor>& band = band_compositors_[static_cast<std::size_t>(w)];
                    start_compositor(band, bands_[b], direct);
                    into = &*band;
                }
                into->add(raster, d->path, fill_options(lw, *d), d->color, lw.layer.opacity, bands_[b]);
            }
            if (banded && into) {
                if (background_due_[b])
                    into->composite_onto(target_, style_.background);
                else
                    into->composite_onto(target_);
                background_due_[b] = 0;
            }
        });
        for (const auto& d : chunk) drew = drew || d.has_value();
    });
    if (!banded && drew) {
        if (background_due_[0]) {  // every band is due, or none
            whole_->composite_onto(target_, style_.background);
            std::fill(background_due_.begin(), background_due_.end(), 0);
        } else {
            whole_->composite_onto(target_);
        }
    }
    paint_background();  // the bands no fill reached
    target_clear_ = target_clear_ && !drew;
}

// Fills with source-over, in feature order (the background is painted).
void MapDrawing::fill_in_order(LayerWork& lw) {
    auto make = [&](int w, std::size_t feature, std::optional<Drawable>& out) { make_fill(lw, w, feature, out); };
    chunked(lw.order, make, [&](const Chunk& chunk) {
        on_regions(bands_, [&](Canvas& canvas, std::size_t b) {
            for (const auto& d : chunk) {
                if (!d || !overlaps(d->box, bands_[b])) continue;
                Paint paint = Paint::solid(d->color);
                paint.opacity = lw.layer.opacity;
                canvas.fill_path(d->path, paint, fill_options(lw, *d));
            }
        });
    });
    target_clear_ = false;
}

// The union of every feature's capsules, drawn from the segments directly (round_stroke.hpp): no
// outline, so nothing folds. The union does not depend on repeats, so a shared border's second
// copy is dropped before the sweep.
void MapDrawing::stroke_sampled(LayerWork& lw) {
    Paint paint = Paint::solid(*lw.line_color);
    paint.opacity = lw.layer.opacity;
    if (lw.covered) {
        target_clear_ = false;
        on_regions(sweeps_, [&](Canvas& canvas, std::size_t k) { lw.cover.composite(k, canvas, paint); });
        return;
    }
    std::vector<LineSegment> segments;
    if (lw.stroke_with_fill) {
        segments = lw.gathered_segments();
    } else {
        auto make_lines = [&](int w, std::size_t feature, std::optional<Drawable>& out) {
            PathVisitor v;
            v.clip = stroke_clip_;
            build(w, feature, v);
            if (!lw.layer.stroke) v.fill.clear();  // a fill colour strokes lines only
            if (!v.lines.empty() || !v.fill.empty())
                out = Drawable{std::move(v.lines), *lw.line_color, std::move(v.fill)};
        };
        Polyline flat;
        chunked(lw.order, make_lines, [&](const Chunk& chunk) {
            for (const auto& d : chunk) {
                if (!d) continue;
                append_segments(d->path, opts_.tolerance, flat, segments);
                append_segments(d->rings, opts_.tolerance, flat, segments);
            }
        });
        drop_repeated_segments(segments);
    }
    if (segments.empty()) return;
    target_clear_ = false;
    on_regions(sweeps_,
               [&](Canvas& canvas, std::size_t) { canvas.fill_round_stroke(segments, 0.5 * ss_.width, paint); });
}

// The outlines of every feature in one path per colour, filled once with the nonzero rule.
// Polygon rings go through SharedBorders first, in feature order, so a border shared by two
// features is stroked once (the union, and so the pixels, stay the same; the exact overlap
// computation along every border is saved).
void MapDrawing::stroke_outlines(LayerWork& lw) {
    StrokeStyle chain_style = ss_;
    chain_style.cap = LineCap::Butt;  // chain ends lie on segments or joins drawn by another chain
    Path outline;
    std::vector<CutCapsule> inside;
    SharedBorders borders;
    const double merge_distance = stroke_merge_distance(Affine{}, opts_.tolerance);
    auto flush = [&] {
        if (outline.empty()) return;
        target_clear_ = false;
        const Rect box = outline.control_bounds();
        Paint paint = Paint::solid(*lw.line_color);
        paint.opacity = lw.layer.opacity;
        on_regions(bands_, [&](Canvas& canvas, std::size_t b) {
            if (!overlaps(box, bands_[b])) return;
            canvas.fill_options() = outline_fo_;
            canvas.fill_options().inside = inside;
            canvas.fill_path(outline, paint, FillRule::NonZero);
            canvas.fill_options() = fo_;
        });
        outline.clear();
        inside.clear();
        borders.clear();  // bounds its memory; a border split by a flush is drawn twice
    };
    auto make_outline = [&](int w, std::size_t feature, std::optional<Drawable>& out) {
        PathVisitor v;
        v.clip = stroke_clip_;
        build(w, feature, v);
        StrokeOutline o;
        // Lines are always stroked; polygon outlines (point disks too) take the stroke colour.
        if (crowded(v.lines, ss_.width))
            o = stroke_outline(v.lines, ss_, Affine{}, opts_.tolerance);
        else if (!v.lines.empty())
            o.outline = stroke(v.lines, ss_, Affine{}, opts_.tolerance);
        Path rings;
        if (lw.layer.stroke && !v.fill.empty()) rings = std::move(v.fill);
        if (!o.outline.empty() || !rings.empty()) {
            out = Drawable{std::move(o.outline), *lw.line_color, std::move(rings)};
            out->inside = std::move(o.inside);
        }
    };
    std::vector<Path> chains, whole;
    chunked(lw.order, make_outline, [&](Chunk& chunk) {
        // What is left of each feature's rings, in feature order, then stroked in parallel.
        chains.assign(chunk.size(), Path{});
        whole.assign(chunk.size(), Path{});
        for (std::size_t i = 0; i < chunk.size(); ++i)
            if (chunk[i] && !chunk[i]->rings.empty()) borders.add(chunk[i]->rings, chains[i], whole[i], merge_distance);
        parallel::for_each_index(threads_, chunk.size(), [&](int, std::size_t i) {
            if (!chains[i].empty()) chunk[i]->path.append(stroke(chains[i], chain_style, Affine{}, opts_.tolerance));
            if (!whole[i].empty()) chunk[i]->path.append(stroke(whole[i], ss_, Affine{}, opts_.tolerance));
            if (chunk[i] && crowded(chunk[i]->rings, ss_.width))
                chunk[i]->ring_inside = stroke_interior(chunk[i]->rings, ss_, Affine{}, opts_.tolerance);
        });
        // A ring's capsules lie inside its whole stroke, which the chains of the rings SharedBorders
        // has seen since its last clear() draw together. A flush clears it after this chunk's rings
        // went in: from then on, the chunk's rings are drawn only in part.
        bool flushed = false;
        for (const auto& d : chunk) {
            if (!d) continue;
            if (outline.points().size() + d->path.points().size() > limits::kMaxPathPoints / 2) {
                flush();
                flushed = true;
            }
            outline.append(d->path);
            inside.insert(inside.end(), d->inside.begin(), d->inside.end());
            if (!flushed) inside.insert(inside.end(), d->ring_inside.begin(), d->ring_inside.end());
        }
    });
    flush();
}

}  // namespace

void draw_map(const MapData& data, const SimplifiedMap* simplified, const MapProjection& proj, const MapFrame& frame,
              const MapStyle& style, const MapOptions& opts, Pixmap& target, bool cleared, KeptMap* cache) {
    if (target.width() != frame.width || target.height() != frame.height)
        throw Error(ErrorKind::InvalidArgument, "render_map: the pixmap does not have the frame's size");
    if (!(opts.simplify >= 0) || !std::isfinite(opts.simplify))
        throw Error(ErrorKind::InvalidArgument, "simplify must be a finite number of pixels >= 0");
    MapDrawing(data, simplified, proj, frame, style, opts, target, cleared, cache).draw();
}

}  // namespace casteljau::map_detail
