// Formats stage, SVG text layout (text_layout.hpp).
//
// characters (per span: one style) --chunks (a new one at every absolute x or y, and at every
// textPath)--> bidi levels per chunk --> per (span, level) segment: fonts (family list, then
// fallback faces) and HarfBuzz shaping (casteljau/shaping.hpp) --> clusters in visual order -->
// positions: dx/dy, letter- and word-spacing, textLength --> text-anchor --> baselines and
// baseline-shift --> rotate or placement along a text path --> glyph outlines and decoration lines
// in user space.
#include "formats/svg/text_layout.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <span>

#include "casteljau/error.hpp"
#include "casteljau/limits.hpp"
#include "casteljau/shaping.hpp"
#include "formats/svg/text_clusters.hpp"

namespace casteljau::svg_text {

namespace {

bool is_word_space(char32_t c) {
    return c == U' ' || c == 0xa0 || c == 0x1361 || c == 0x10100 || c == 0x10101 || c == 0x3000;
}

// An arc-length parametrised polyline of a path (curves sampled finely enough for glyph placement).
struct PathWalker {
    std::vector<Point> pts;
    std::vector<double> len;  // cumulative length at each point
    std::vector<bool> jump;   // pts[i] starts a new subpath (no segment from pts[i-1])

    // A path that cannot be flattened (non-finite, or too many segments) carries no text.
    explicit PathWalker(const Path& path) {
        Polyline poly;
        try {
            flatten(path, Affine{}, 0.01, poly);
        } catch (const Error&) { return; }
        std::uint32_t start = 0;
        for (std::size_t c = 0; c < poly.contour_count(); ++c) {
            const std::uint32_t end = poly.contour_ends[c];
            for (std::uint32_t i = start; i < end; ++i) {
                const bool first = i == start;
                const Point p = poly.points[i];
                if (pts.empty())
                    len.push_back(0);
                else
                    len.push_back(len.back() + (first ? 0 : std::hypot(p.x - pts.back().x, p.y - pts.back().y)));
                pts.push_back(p);
                jump.push_back(first);
            }
            if (poly.closed[c] && end > start) {
                const Point p = poly.points[start];
                len.push_back(len.back() + std::hypot(p.x - pts.back().x, p.y - pts.back().y));
                pts.push_back(p);
                jump.push_back(false);
            }
            start = end;
        }
    }
    double total() const { return len.empty() ? 0 : len.back(); }
    // Point and direction (radians) at distance d along the path.
    bool at(double d, Point& p, double& angle) const {
        if (pts.size() < 2 || d < 0 || d > total()) return false;
        std::size_t i = static_cast<std::size_t>(std::upper_bound(len.begin(), len.end(), d) - len.begin());
        if (i >= pts.size()) i = pts.size() - 1;
        while (i > 0 && (jump[i] || len[i] == len[i - 1]) && i + 1 < pts.size()) ++i;
        if (i == 0) i = 1;
        const Point a = pts[i - 1], b = pts[i];
        const double seg = len[i] - len[i - 1];
        const double t = seg > 0 ? std::clamp((d - len[i - 1]) / seg, 0.0, 1.0) : 0;
        p = {a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t};
        angle = std::atan2(b.y - a.y, b.x - a.x);
        return true;
    }
};

// Offset of the baseline (px, y down) for a dominant or alignment baseline.
double baseline_offset(Baseline b, const Font* font, double size) {
    if (!font) return 0;
    const FontMetrics& m = font->metrics();
    const double s = size / m.units_per_em;
    switch (b) {
        case Baseline::Alphabetic: return 0;
        case Baseline::Middle: return m.x_height / 2 * s;
        case Baseline::Central: return (m.ascender + m.descender) / 2 * s;
        case Baseline::Hanging: return m.ascender * 0.8 * s;
        case Baseline::Mathematical: return m.ascender * 0.5 * s;
        case Baseline::TextTop: return m.ascender * s;
        case Baseline::TextBottom:
        case Baseline::Ideographic: return m.descender * s;
    }
    return 0;
}

// The characters of all spans in one string, with the span each comes from.
struct FlatText {
    std::u32string text;
    std::vector<std::size_t> span_of;
};

FlatText flat_text(const TextInput& in) {
    FlatText t;
    for (std::size_t s = 0; s < in.spans.size(); ++s) {
        t.text += in.spans[s].text;
        t.span_of.insert(t.span_of.end(), in.spans[s].text.size(), s);
    }
    return t;
}

// The x, y, dx, dy and rotate values of character i (none past the end of the lists).
const CharPos& char_pos(const TextInput& in, std::size_t i) {
    static const CharPos none;
    return i < in.pos.size() ? in.pos[i] : none;
}

// Chunks: a new one at every absolute position and wherever the text path changes. Their
// starts, then the text's length.
std::vector<std::size_t> chunk_starts(const TextInput& in, const FlatText& t) {
    const std::size_t n = t.text.size();
    std::vector<std::size_t> starts{0};
    for (std::size_t i = 1; i < n; ++i)
        if (char_pos(in, i).x || char_pos(in, i).y ||
            in.spans[t.span_of[i]].path_element != in.spans[t.span_of[i - 1]].path_element)
            starts.push_back(i);
    starts.push_back(n);
    return starts;
}

// The clusters of one shaped run, in its visual order, with its bidi level.
struct RunClusters {
    std::uint8_t level;
    std::vector<Cluster> clusters;
};

// The clusters of `run` that belong to the segment [sb, se) (the run was shaped over the wider
// window starting at wb, for context), each with its glyphs placed along the run's direction.
RunClusters run_clusters(const ShapedRun& run, const std::vector<const Font*>& shaped_fonts, std::size_t wb,
                         std::size_t sb, std::size_t se, std::size_t span, bool upright) {
    RunClusters rc;
    rc.level = run.level;
    // Cluster starts in logical order, to know how many characters each one covers.
    std::vector<std::uint32_t> starts;
    for (const auto& g : run.glyphs) starts.push_back(g.cluster);
    std::sort(starts.begin(), starts.end());
    starts.erase(std::unique(starts.begin(), starts.end()), starts.end());
    for (std::size_t g = 0; g < run.glyphs.size();) {
        const std::uint32_t cl = run.glyphs[g].cluster;
        if (wb + cl < sb || wb + cl >= se) {  // context: another segment's glyph
            ++g;
            continue;
        }
        Cluster k;
        k.ch = wb + cl;
        const auto next = std::upper_bound(starts.begin(), starts.end(), cl);
        k.nch = std::min<std::size_t>(wb + (next == starts.end() ? run.end : *next), se) - k.ch;
        k.span = span;
        k.font = shaped_fonts[run.glyphs[g].font];
        k.upright = upright;
        double pen = 0;
        for (; g < run.glyphs.size() && run.glyphs[g].cluster == cl; ++g) {
            const auto& sg = run.glyphs[g];
            k.glyphs.push_back({shaped_fonts[sg.font], sg.glyph, pen + sg.x_offset, -sg.y_offset});
            pen += sg.advance;
        }
        k.advance = pen;
        rc.clusters.push_back(std::move(k));
    }
    return rc;
}

// One chunk [cb, ce) being shaped: its bidi levels and the runs shaped so far.
struct ChunkShaping {
    const TextInput& in;
    const FlatText& t;
    std::size_t cb, ce;
    const std::vector<std::uint8_t>& levels;
    std::vector<ShapedRun>& runs;  // scratch, reused from segment to segment
    std::vector<RunClusters> all_runs;
};

// Shapes the segment [sb, se) of the chunk (one span, one bidi level, one orientation) and adds
// its runs' clusters; false when no font has its characters.
bool shape_segment(ChunkShaping& c, FontSet& fonts, std::size_t sb, std::size_t se, bool upright) {
    const TextInput& in = c.in;
    const std::u32string& text = c.t.text;
    const std::size_t cb = c.cb, ce = c.ce;
    const std::vector<std::uint8_t>& levels = c.levels;
    const Span& span = in.spans[c.t.span_of[sb]];
    const std::u32string_view seg(text.data() + sb, se - sb);
    const std::vector<const Font*> chain = fonts.chain(span.font, seg);
    if (chain.empty()) return false;
    TextStyle ts;
    ts.size = span.font.size;
    ts.features = span.font.features;
    SystemFontFallback* system = fonts.system(*chain[0]);
    std::unique_ptr<TextShaper> shaper;
    try {
        shaper = std::make_unique<TextShaper>(std::span<const Font* const>(chain), ts, false, system);
    } catch (const Error&) {
        ts.features.clear();
        shaper = std::make_unique<TextShaper>(std::span<const Font* const>(chain), ts, false, system);
    }
    // Shaped with up to kContext neighbours of the same level on each side (from other
    // spans too), so that kerning and joining work across tspans; only the segment's own
    // glyphs are kept.
    constexpr std::size_t kContext = 32;
    std::size_t wb = sb, we = se;
    while (wb > cb && sb - wb < kContext && levels[wb - 1 - cb] == levels[sb - cb] &&
           (!in.vertical || is_upright(text[wb - 1]) == upright))
        --wb;
    while (we < ce && we - se < kContext && levels[we - cb] == levels[sb - cb] &&
           (!in.vertical || is_upright(text[we]) == upright))
        ++we;
    const std::u32string_view window(text.data() + wb, we - wb);
    shaper->shape_paragraph(window, std::span<const std::uint8_t>(levels.data() + (wb - cb), we - wb), c.runs);
    const std::vector<const Font*>& shaped_fonts = shaper->fonts();  // the chain, then system fonts
    for (const ShapedRun& run : c.runs) {
        RunClusters rc = run_clusters(run, shaped_fonts, wb, sb, se, c.t.span_of[sb], upright);
        for (Cluster& k : rc.clusters) k.primary = chain[0];
        if (!rc.clusters.empty()) c.all_runs.push_back(std::move(rc));
    }
    return true;
}

// The clusters of the chunk [cb, ce) in visual order: bidi levels, then one segment per span,
// level and orientation shaped on its own. `warned_fonts`: a missing font was reported already.
std::vector<Cluster> shape_chunk(const TextInput& in, const FlatText& t, FontSet& fonts, std::size_t cb, std::size_t ce,
                                 std::vector<std::uint8_t>& levels, std::vector<ShapedRun>& runs,
                                 std::vector<std::string>& warnings, bool& warned_fonts) {
    const std::u32string& text = t.text;
    const std::u32string_view ctext(text.data() + cb, ce - cb);
    resolve_bidi_levels(ctext, in.direction, levels);
    ChunkShaping c{in, t, cb, ce, levels, runs, {}};
    for (std::size_t sb = cb; sb < ce;) {
        std::size_t se = sb + 1;
        const bool upright = in.vertical && is_upright(text[sb]);
        while (se < ce && t.span_of[se] == t.span_of[sb] && levels[se - cb] == levels[sb - cb] &&
               (!in.vertical || is_upright(text[se]) == upright))
            ++se;
        if (!shape_segment(c, fonts, sb, se, upright)) {
            if (!warned_fonts) warnings.push_back("no font found for text; text not drawn");
            warned_fonts = true;
        }
        sb = se;
    }
    std::vector<std::uint8_t> run_levels;
    for (const RunClusters& r : c.all_runs) run_levels.push_back(r.level);
    std::vector<std::size_t> order;
    bidi_visual_order(run_levels, order);
    std::vector<Cluster> clusters;
    for (std::size_t i : order)
        for (Cluster& k : c.all_runs[i].clusters) clusters.push_back(std::move(k));
    return clusters;
}

// The coordinate a cluster advances along: y in vertical text, x otherwise.
double& along(Cluster& g, bool vert) { return vert ? g.y : g.x; }

// textLength on the ranges inside the chunk `cl`: stretches or squeezes their spacing (or, with
// lengthAdjust spacingAndGlyphs, their glyphs too) and moves what follows them.
void apply_text_lengths(const TextInput& in, std::vector<Cluster>& cl, bool vert, double& pen_along) {
    for (const LengthRange& lr : in.lengths) {
        std::vector<Cluster*> in_range;
        for (Cluster& g : cl)
            if (g.ch >= lr.begin && g.ch < lr.end) in_range.push_back(&g);
        if (in_range.empty() || !(lr.length >= 0)) continue;
        double lo = along(*in_range.front(), vert), hi = lo;
        for (Cluster* g : in_range) {
            lo = std::min(lo, along(*g, vert));
            hi = std::max(hi, along(*g, vert) + g->advance);
        }
        const double width = hi - lo;
        if (!(width > 0)) continue;
        double shift_after = 0;
        if (lr.spacing_and_glyphs) {
            const double s = lr.length / width;
            for (Cluster* g : in_range) {
                along(*g, vert) = lo + (along(*g, vert) - lo) * s;
                g->scale_x = s;
                g->step *= s;
            }
            shift_after = lr.length - width;
        } else if (in_range.size() > 1) {
            const double extra = (lr.length - width) / static_cast<double>(in_range.size() - 1);
            for (std::size_t i = 0; i < in_range.size(); ++i)
                along(*in_range[i], vert) += extra * static_cast<double>(i);
            shift_after = lr.length - width;
        }
        bool after = false;
        for (Cluster& g : cl) {
            if (after) along(g, vert) += shift_after;
            if (&g == in_range.back()) after = true;
        }
        pen_along += shift_after;
    }
}

// text-anchor `a` (the chunk's first character's) on the chunk `cl`, which started at `start`:
// the chunk's whole advance counts, white space at its end included (SVG 2). As in resvg, start
// is the left end in right-to-left text too (CSS would take the right end).
void apply_anchor(Anchor a, std::vector<Cluster>& cl, bool vert, double start) {
    if (cl.empty()) return;
    double lo = along(cl.front(), vert), hi = lo;
    for (std::size_t k = 0; k < cl.size(); ++k) {
        lo = std::min(lo, along(cl[k], vert));
        hi = std::max(hi, along(cl[k], vert) + cl[k].advance * cl[k].scale_x);
    }
    const double width = hi - std::min(lo, start);
    const double shift = a == Anchor::Middle ? width / 2 : a == Anchor::End ? width : 0;
    for (Cluster& g : cl) along(g, vert) -= shift;
    if (cl.size() > 0) cl.back().step = cl.back().advance * cl.back().scale_x;
}

// Positions the clusters of every chunk: the pen carries on from chunk to chunk; absolute x and
// y, text paths' start offsets, dx and dy move it; letter- and word-spacing, textLength and
// text-anchor follow.
void position_chunks(const TextInput& in, const FlatText& t, const std::vector<std::size_t>& starts,
                     std::vector<std::vector<Cluster>>& chunks) {
    const std::size_t n = t.text.size();
    double pen_x = 0, pen_y = 0;
    for (std::size_t c = 0; c < chunks.size(); ++c) {
        std::vector<Cluster>& cl = chunks[c];
        const std::size_t cb = starts[c];
        const Span& first_span = in.spans[t.span_of[cb]];
        const bool on_path = first_span.path >= 0;
        const int prev_path = c > 0 ? in.spans[t.span_of[starts[c - 1]]].path : -1;
        if (!on_path && prev_path >= 0) {
            // Text after a text path goes on from where the path's text ended.
            const PathWalker w(in.paths[static_cast<std::size_t>(prev_path)].path);
            Point p;
            double angle = 0;
            if (w.at(std::clamp(pen_x, 0.0, w.total()), p, angle)) {
                pen_x = p.x;
                pen_y = p.y;
            }
        }
        if (char_pos(in, cb).x) pen_x = *char_pos(in, cb).x;
        if (char_pos(in, cb).y) pen_y = *char_pos(in, cb).y;
        if (on_path) {
            const bool first = c == 0 || in.spans[t.span_of[starts[c - 1]]].path_element != first_span.path_element;
            const double offset = in.paths[static_cast<std::size_t>(first_span.path)].start_offset;
            if (char_pos(in, cb).x)
                pen_x = *char_pos(in, cb).x + offset;  // an absolute x is a distance along the path
            else if (first)
                pen_x = offset;
            if (first) pen_y = 0;  // dy moves glyphs off the path
        }
        // Vertical text advances along y; `pen_along` is the pen's coordinate that advances.
        const bool vert = in.vertical && !on_path;
        double& pen_along = vert ? pen_y : pen_x;
        const double start_x = pen_along;
        for (std::size_t k = 0; k < cl.size(); ++k) {
            Cluster& g = cl[k];
            for (std::size_t i = g.ch; i < g.ch + g.nch && i < n; ++i) {
                if (char_pos(in, i).dx) pen_x += *char_pos(in, i).dx;
                if (char_pos(in, i).dy) pen_y += *char_pos(in, i).dy;
            }
            g.x = pen_x;
            g.y = pen_y;
            const Span& sp = in.spans[g.span];
            double step = g.advance + (letter_spacing_allowed(t.text[g.ch]) ? sp.letter_spacing : 0);
            if (is_word_space(t.text[g.ch])) step += sp.word_spacing;
            g.step = step;
            pen_along += step;
        }
        apply_text_lengths(in, cl, vert, pen_along);
        apply_anchor(first_span.anchor, cl, vert, start_x);
    }
}

// The outlines of a text being built: one path per (layer, style), with the decoration lines
// gathered so that a line continued by the next cluster becomes one rectangle (a stroke outlines
// the run, not every glyph's piece).
class OutlineSink {
public:
    explicit OutlineSink(std::vector<Outline>& out) : out_(out) {}

    Path& outline_for(Outline::Layer layer, std::size_t style) {
        for (Outline& o : out_)
            if (o.layer == layer && o.style == style) return o.path;
        out_.push_back({layer, style, Path()});
        return out_.back().path;
    }

    // A decoration line of `width` from the origin of `t`, `top` and `thick` across it.
    void decorate(const Decoration& d, const Affine& t, double top, double thick, double width) {
        for (PendingLine& p : pending_) {
            if (p.d.kind != d.kind || p.d.style != d.style) continue;
            const Point end = p.t.apply({p.width, 0});
            const bool continues = std::fabs(end.x - t.e) < 1e-6 && std::fabs(end.y - t.f) < 1e-6 && p.t.a == t.a &&
                                   p.t.b == t.b && p.t.c == t.c && p.t.d == t.d && p.top == top && p.thick == thick;
            if (continues) {
                p.width += width;
                return;
            }
            flush_line(p);
            p = {d, t, top, thick, width};
            return;
        }
        pending_.push_back({d, t, top, thick, width});
    }

    // Adds the decoration lines gathered so far.
    void flush_decorations() {
        for (const PendingLine& p : pending_) flush_line(p);
        pending_.clear();
    }

private:
    struct PendingLine {
        Decoration d;
        Affine t;
        double top = 0, thick = 0, width = 0;
    };

    void flush_line(const PendingLine& p) {
        Path r;
        r.add_rect(Rect::from_xywh(0, p.top, p.width, p.thick));
        outline_for(p.d.kind == Decoration::LineThrough ? Outline::Over : Outline::Under, p.d.style).append(r, p.t);
    }

    std::vector<Outline>& out_;
    std::vector<PendingLine> pending_;
};

// The baseline shift of cluster `g` of span `sp` (px, up): baseline-shift values, sub and super.
double baseline_shift(const Span& sp, const Cluster& g) {
    const double size = sp.font.size;
    double shift = 0;
    for (const Span::Shift& bs : sp.baseline_shifts) {
        const double s = g.font ? size / g.font->units_per_em() : 0;
        if (bs.kind == 0)
            shift += bs.value;
        else if (bs.kind == 1)
            shift -= g.font ? g.font->metrics().subscript_offset * s : 0.2 * size;
        else
            shift += g.font ? g.font->metrics().superscript_offset * s : 0.4 * size;
    }
    return shift;
}

// Cluster space (origin on the baseline, y down) -> user space for cluster `g`: on its text path,
// in vertical text, or on its line; rotate and textLength's glyph scale applied. nullopt when it
// falls off its text path.
std::optional<Affine> cluster_transform(const TextInput& in, const Cluster& g,
                                        std::vector<std::unique_ptr<PathWalker>>& walkers) {
    const Span& sp = in.spans[g.span];
    const double size = sp.font.size;
    const double shift = baseline_shift(sp, g);
    const double by = g.y + baseline_offset(sp.baseline, g.font, size) - shift;
    Affine t;
    if (sp.path >= 0) {
        auto& w = walkers[static_cast<std::size_t>(sp.path)];
        if (!w) w = std::make_unique<PathWalker>(in.paths[static_cast<std::size_t>(sp.path)].path);
        const double half = g.advance * g.scale_x / 2;
        Point p;
        double angle = 0;
        if (!w->at(g.x + half, p, angle)) return std::nullopt;  // off the path: not drawn
        t = Affine::translate(p.x, p.y) * Affine::rotate(angle) * Affine::translate(-half, by);
        if (g.ch < in.pos.size() && in.pos[g.ch].rotate) t = t * Affine::rotate_degrees(*in.pos[g.ch].rotate);
        if (in.vertical) t = t * vertical_on_path(in, g);
    } else if (in.vertical) {
        t = vertical_cluster_transform(in, g, shift);
    } else {
        t = Affine::translate(g.x, by);
        if (g.ch < in.pos.size() && in.pos[g.ch].rotate) t = t * Affine::rotate_degrees(*in.pos[g.ch].rotate);
    }
    return t * Affine::scale(g.scale_x, 1);
}

// The decoration lines of cluster `g` of span `sp`, placed by `t`, centred on the font's offset
// for each line (resvg and browsers); `vertical`: `t` is the frame of vertical text's line.
void decorate_cluster(const Span& sp, const Cluster& g, const Affine& t, bool vertical, OutlineSink& sink) {
    if (sp.decorations.empty() || !g.font) return;
    const FontMetrics& m = (vertical && g.primary ? g.primary : g.font)->metrics();
    const double s = sp.font.size / m.units_per_em;
    const double w = g.step / g.scale_x;
    for (const Decoration& d : sp.decorations) {
        double centre = 0, thick = 0;
        if (vertical) {
            // Along the line's frame, as resvg draws them (the specifications leave the
            // offsets open): underline and overline half the line height of the span's first
            // font to each side.
            thick = m.underline_thickness > 0 ? m.underline_thickness : m.units_per_em / 14.0;
            const double half = (m.ascender - m.descender) / 2;
            centre = d.kind == Decoration::Underline ? -half : d.kind == Decoration::Overline ? half : 0;
            sink.decorate(d, t, (-centre - thick / 2) * s, thick * s, w);
            continue;
        }
        if (d.kind == Decoration::Underline) {
            thick = m.underline_thickness > 0 ? m.underline_thickness : m.units_per_em / 14.0;
            centre = m.underline_position;
        } else if (d.kind == Decoration::Overline) {
            thick = m.underline_thickness > 0 ? m.underline_thickness : m.units_per_em / 14.0;
            centre = m.ascender;
        } else {
            thick = m.strikeout_thickness > 0 ? m.strikeout_thickness : m.units_per_em / 14.0;
            centre = m.strikeout_position > 0 ? m.strikeout_position : m.x_height / 2;
        }
        sink.decorate(d, t, (-centre - thick / 2) * s, thick * s, w);
    }
}

// The glyph outlines and decoration lines of every positioned cluster, and the text's box (the
// union of the clusters' cells) when `box` is given.
void outline_chunks(const TextInput& in, const std::vector<std::vector<Cluster>>& chunks, std::vector<Outline>& out,
                    std::optional<Rect>* box, const FontSet& fonts, std::vector<ColorGlyph>* color) {
    OutlineSink sink(out);
    std::vector<std::unique_ptr<PathWalker>> walkers(in.paths.size());
    VerticalDecorationFrames frames;
    Path glyph;
    for (const std::vector<Cluster>& cl : chunks) {
        frames.next_chunk();
        for (const Cluster& g : cl) {
            const Span& sp = in.spans[g.span];
            const double size = sp.font.size;
            const std::optional<Affine> placed = cluster_transform(in, g, walkers);
            if (!placed) continue;
            const Affine& t = *placed;
            // Spacing or positions beyond double range, or so far out (past limits::kMaxCoordinate
            // user units) that no canvas shows them and the rasterizer refuses them: not drawn.
            if (!t.is_finite() || std::max(std::fabs(t.e), std::fabs(t.f)) > limits::kMaxCoordinate) continue;
            if (box && g.font) {
                // The cluster's cell: its advance by the font's ascender to descender.
                const FontMetrics& m = g.font->metrics();
                const double s = size / m.units_per_em;
                const Rect cell = transform_bounds(t, Rect{0, -m.ascender * s, g.advance, -m.descender * s});
                *box = *box ? (*box)->united(cell) : cell;
            }
            for (const Glyph& gl : g.glyphs) {
                const double s = size / gl.font->units_per_em();
                if (color && is_color_glyph(*gl.font, gl.id)) {
                    if (std::shared_ptr<const Font> f = fonts.shared(gl.font)) {
                        color->push_back(
                            {sp.style, std::move(f), gl.id, size, t * Affine::translate(gl.x_off, gl.y_off)});
                        continue;
                    }
                }
                try {
                    gl.font->glyph_path(gl.id, glyph);
                } catch (const Error&) { continue; }
                if (glyph.empty()) continue;
                sink.outline_for(Outline::Glyphs, sp.style)
                    .append(glyph, t * Affine::translate(gl.x_off, gl.y_off) * Affine::scale(s, -s));
            }
            if (in.vertical && sp.path < 0)
                decorate_cluster(sp, g, frames.frame(in, g, baseline_shift(sp, g)), true, sink);
            else
                decorate_cluster(sp, g, t, false, sink);
        }
        sink.flush_decorations();
    }
}

}  // namespace

std::vector<Outline> layout(const TextInput& in, FontSet& fonts, std::vector<std::string>& warnings,
                            std::optional<Rect>* box, std::vector<ColorGlyph>* color) {
    const FlatText t = flat_text(in);
    std::vector<Outline> out;
    if (t.text.empty()) return out;
    const std::vector<std::size_t> starts = chunk_starts(in, t);
    std::vector<std::vector<Cluster>> chunks;
    std::vector<std::uint8_t> levels;
    std::vector<ShapedRun> runs;
    bool warned_fonts = false;
    for (std::size_t c = 0; c + 1 < starts.size(); ++c)
        chunks.push_back(shape_chunk(in, t, fonts, starts[c], starts[c + 1], levels, runs, warnings, warned_fonts));
    position_chunks(in, t, starts, chunks);
    outline_chunks(in, chunks, out, box, fonts, color);
    return out;
}

}  // namespace casteljau::svg_text
