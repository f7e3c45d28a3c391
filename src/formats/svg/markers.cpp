// Formats stage, SVG conversion: markers drawn at the vertices of a shape.
#include "formats/svg/context.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace casteljau::svg {

namespace {

// A vertex of the marked path with the directions of the segments coming in and going out (none
// at an open end, or where every control point coincides with the vertex).
struct MarkerVertex {
    Point p;
    std::optional<Vec> in, out;
};

// The path's vertices in order: every segment's end, and each subpath's start. A closed
// subpath's end vertex turns into its first segment, and its start vertex comes in from its
// closing segment.
class VertexCollector {
public:
    std::vector<MarkerVertex> vs;

    void move(Point p) {
        first_ = vs.size();
        vs.push_back({p, std::nullopt, std::nullopt});
    }
    void line(Point a, Point b) { segment(a, {b}); }
    void quad(Point a, Point c, Point b) { segment(a, {c, b}); }
    void cubic(Point a, Point c1, Point c2, Point b) { segment(a, {c1, c2, b}); }
    void conic(Point a, Point c, Point b, double) { segment(a, {c, b}); }
    void close(Point last, Point first) {
        if (!(last == first)) segment(last, {first});
        if (first_ < vs.size()) {
            vs.back().out = vs[first_].out;
            vs[first_].in = vs.back().in;
        }
    }

private:
    static std::optional<Vec> dir(Point a, Point b) {
        const Vec d{b.x - a.x, b.y - a.y};
        if (d.x == 0 && d.y == 0) return std::nullopt;
        return d;
    }
    // A segment from p0 through `rest`: its start direction towards the first control point apart
    // from p0, its end direction from the last one apart from its end.
    void segment(Point p0, std::initializer_list<Point> rest) {
        std::vector<Point> pts{p0};
        pts.insert(pts.end(), rest.begin(), rest.end());
        std::optional<Vec> start, end;
        for (std::size_t i = 1; i < pts.size() && !start; ++i) start = dir(p0, pts[i]);
        for (std::size_t i = pts.size() - 1; i-- > 0 && !end;) end = dir(pts[i], pts.back());
        if (!vs.empty() && !vs.back().out) vs.back().out = start;
        vs.push_back({pts.back(), end, std::nullopt});
    }
    std::size_t first_ = 0;  // the current subpath's first vertex
};

// An angle with an optional unit (deg, grad, rad, turn; degrees without one), in radians; 0 when
// invalid.
double parse_angle(std::string_view o) {
    double unit = kPi / 180;
    // "grad" before "rad": both end in "rad".
    if (o.size() > 3 && o.substr(o.size() - 3) == "deg") {
        o.remove_suffix(3);
    } else if (o.size() > 4 && o.substr(o.size() - 4) == "grad") {
        o.remove_suffix(4);
        unit = kPi / 200;
    } else if (o.size() > 3 && o.substr(o.size() - 3) == "rad") {
        o.remove_suffix(3);
        unit = 1;
    } else if (o.size() > 4 && o.substr(o.size() - 4) == "turn") {
        o.remove_suffix(4);
        unit = 2 * kPi;
    }
    const auto n = parse_number(o);
    return n ? *n * unit : 0;
}

// The marker's rotation at vertex v (radians): orient auto bisects the directions in and out,
// auto-start-reverse turns the first vertex's by a half turn, an angle is itself.
double marker_angle(const pugi::xml_node& marker, const MarkerVertex& v, bool first) {
    const std::string_view orient = trim(marker.attribute("orient").value());
    if (orient != "auto" && orient != "auto-start-reverse") return orient.empty() ? 0 : parse_angle(orient);
    double angle = 0;
    const std::optional<Vec>& a = v.in ? v.in : v.out;
    const std::optional<Vec>& b = v.out ? v.out : v.in;
    if (a && b) {
        const double ai = std::atan2(a->y, a->x), ao = std::atan2(b->y, b->x);
        angle = (ai + ao) / 2;
        if (std::fabs(ai - ao) > kPi) angle += kPi;
    }
    if (orient == "auto-start-reverse" && first) angle += kPi;
    return angle;
}

}  // namespace

// Markers at the vertices of `path`: marker-start at the first, marker-end at the last,
// marker-mid at the others; each oriented (orient auto / auto-start-reverse / an angle),
// scaled by the stroke width (markerUnits strokeWidth), mapped by its viewBox and refX/refY,
// and clipped to markerWidth x markerHeight unless overflow is visible.
void emit_markers(Context& cx, const Path& path, const Style& st, const Affine& cm, Viewport vp, int depth) {
    if (st.marker_start.empty() && st.marker_mid.empty() && st.marker_end.empty()) return;
    VertexCollector collect;
    path.visit(collect);
    const std::vector<MarkerVertex>& vs = collect.vs;
    std::shared_ptr<const ContextElement> context;  // the marked shape, for context-fill/-stroke
    for (std::size_t i = 0; i < vs.size(); ++i) {
        const std::string& id = i == 0 ? st.marker_start : i + 1 == vs.size() ? st.marker_end : st.marker_mid;
        if (id.empty()) continue;
        const pugi::xml_node marker = lookup(cx, id);
        if (!marker || std::string_view(marker.name()) != "marker" || is_active(cx, marker)) continue;
        const double angle = marker_angle(marker, vs[i], i == 0);
        if (!context) context = std::make_shared<const ContextElement>(ContextElement{path, cm, vp});
        emit_marker(cx, marker, st, context, cm * Affine::translate(vs[i].p.x, vs[i].p.y) * Affine::rotate(angle), vp,
                    depth);
    }
}

void emit_marker(Context& cx, const pugi::xml_node& marker, const Style& st,
                 const std::shared_ptr<const ContextElement>& context, const Affine& at, Viewport vp, int depth) {
    double scale = 1;
    if (std::string_view(marker.attribute("markerUnits").value()) != "userSpaceOnUse") scale = st.stroke_style.width;
    if (!(scale > 0)) return;
    const double mw = length_attr(cx, marker, "markerWidth", vp.w, 3);
    const double mh = length_attr(cx, marker, "markerHeight", vp.h, 3);
    if (!(mw > 0) || !(mh > 0)) return;
    Affine vbt;
    Viewport inner_vp{mw, mh};
    if (auto vb = parse_viewbox(marker.attribute("viewBox").value())) {
        vbt = viewbox_transform(*vb, marker.attribute("preserveAspectRatio").value(), mw, mh);
        inner_vp = {vb->width(), vb->height()};
    }
    // Percentages of refX and refY, like those of markerWidth and markerHeight, are of the
    // viewport the marked shape is in.
    const Point ref = vbt.apply({length_attr(cx, marker, "refX", vp.w), length_attr(cx, marker, "refY", vp.h)});
    const Affine box = at * Affine::scale(scale) * Affine::translate(-ref.x, -ref.y);
    const Affine content_m = box * vbt;
    // overflow: hidden unless set (the user agent style of marker); `inherit` takes the
    // parent's computed value: what it sets, or the initial value visible when it sets none.
    std::string overflow = own_overflow(cx, marker);
    for (pugi::xml_node a = marker.parent(); overflow == "inherit"; a = a.parent()) {
        overflow = a && a.type() == pugi::node_element ? own_overflow(cx, a) : "";
        if (overflow.empty()) overflow = "visible";
    }
    const bool clip = !(overflow == "visible" || overflow == "auto");
    cx.active_refs.push_back(marker);
    Style mst;
    mst.context_fill = context_paint(st.fill, context);
    mst.context_stroke = context_paint(st.stroke, context);
    apply_style(cx, marker, mst);
    cx.items.push_back(layer_item(DisplayItem::BeginLayer, 1));
    walk(cx, marker, mst, content_m, inner_vp, depth + 1);
    if (clip) {
        DisplayItem begin;
        begin.kind = DisplayItem::BeginClip;
        cx.items.push_back(std::move(begin));
        DisplayItem r;
        r.kind = DisplayItem::Fill;
        r.path.add_rect(Rect::from_xywh(0, 0, mw, mh));
        r.transform = box;
        cx.items.push_back(std::move(r));
        DisplayItem end;
        end.kind = DisplayItem::EndMask;
        cx.items.push_back(std::move(end));
    }
    cx.items.push_back(layer_item(DisplayItem::EndLayer, 1));
    cx.active_refs.pop_back();
}

}  // namespace casteljau::svg
