// Formats stage, SVG conversion: paints resolved for a shape: solid colours and the linearGradient
// and radialGradient paint servers (patterns: pattern.cpp).
#include "formats/svg/context.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace casteljau::svg {

// Sets the colour or shader of `it` for `ref` drawn on `path` (user space, for
// objectBoundingBox units); false when nothing is to be painted.
// resolve_paint for an element drawn with `cm` (its user space -> document pixels): a context
// paint server is resolved for the context element, in its user space, then mapped into ours.
bool resolve_paint(Context& cx, const PaintRef& ref, const Path& path, const Affine& cm, Viewport vp, DisplayItem& it) {
    if (ref.kind != PaintRef::Server || !ref.context) return resolve_paint(cx, ref, path, vp, it);
    const ContextElement& ctx = *ref.context;
    if (!resolve_paint(cx, ref, ctx.path, ctx.viewport, it)) return false;
    const auto inv = cm.inverse();
    if (!inv) return false;
    const Affine rel = *inv * ctx.transform;  // context user space -> this element's user space
    if (it.shader) it.shader = std::make_shared<const Shader>(it.shader->transformed(rel));
    if (it.pattern) {
        auto tile = std::make_shared<PatternTile>(*it.pattern);
        tile->transform = rel * tile->transform;
        it.pattern = std::move(tile);
    }
    return true;
}

bool resolve_paint(Context& cx, const PaintRef& ref, const Path& path, Viewport vp, DisplayItem& it) {
    if (ref.kind == PaintRef::None) return false;
    if (ref.kind == PaintRef::Solid) {
        it.color = ref.color;
        return true;
    }
    const pugi::xml_node server = lookup(cx, ref.id);
    const std::string_view kind = server ? server.name() : "";
    if (kind == "linearGradient" || kind == "radialGradient") {
        if (gradient(cx, server, path, vp, it)) return true;
        // An unusable gradient (no stops) takes the fallback colour when there is one.
        if (ref.fallback != PaintRef::Solid) return false;
        it.shader.reset();
        it.color = ref.fallback_color;
        return true;
    }
    if (!server || ref.fallback != PaintRef::None) {
        if (ref.fallback == PaintRef::Solid) {
            it.color = ref.fallback_color;
            return true;
        }
        if (!server) warn(cx, "paint server '#" + ref.id + "' not found; painted as none");
        return false;
    }
    if (kind == "pattern") {
        if (pattern(cx, server, path, vp, it)) return true;
        if (ref.fallback != PaintRef::Solid) return false;
        it.color = ref.fallback_color;
        return true;
    }
    warn(cx, "<" + std::string(kind) + "> is not a paint server; painted as none");
    return false;
}

namespace {

// One gradient stop: its offset (a number or a percentage, clamped to [0, 1] and to at least the
// previous stop's) and its colour with stop-opacity.
GradientStop read_stop(Context& cx, const pugi::xml_node& s, const std::vector<GradientStop>& before) {
    GradientStop st;
    const std::string_view off = trim(s.attribute("offset").value());
    double o = 0;
    if (!off.empty() && off.back() == '%') {
        if (auto v = parse_number(off.substr(0, off.size() - 1))) o = *v / 100;
    } else if (auto v = parse_number(off)) {
        o = *v;
    }
    st.offset = std::clamp(o, 0.0, 1.0);
    if (!before.empty()) st.offset = std::max(st.offset, before.back().offset);
    Color color = Color::black();
    double opacity = 1;
    for (const auto& [k, v] : properties(cx, s)) {
        std::string val(trim(v));
        // stop-color and stop-opacity are not inherited: `inherit` takes the parent's own value,
        // or the initial one.
        if (val == "inherit") val = k == "stop-color" || k == "stop-opacity" ? own_property(cx, s.parent(), k) : "";
        if (k == "stop-color" && !val.empty()) {
            if (val == "currentColor") val = inherited(cx, s, "color");
            try {
                color = parse_color(val.empty() ? "black" : val);
            } catch (const Error&) { warn(cx, "invalid stop-color '" + v + "'"); }
        } else if (k == "stop-opacity") {
            if (auto op = parse_opacity(val)) opacity = *op;
        }
    }
    st.color = color.with_opacity(opacity);
    return st;
}

// A linearGradient or radialGradient with its href chain: attributes come from the first element
// of the chain that has them, stops from the first that has any.
class GradientReader {
public:
    GradientReader(Context& cx, const pugi::xml_node& node, Viewport vp)
        : cx_(cx),
          node_(node),
          vp_(vp),
          chain_(href_chain(node, [&](std::string_view id) { return lookup(cx, id); },
                            {"linearGradient", "radialGradient"})),
          kind_(node.name()),
          bbox_units_(attr("gradientUnits", false) != "userSpaceOnUse") {}

    bool linear() const { return kind_ == "linearGradient"; }
    bool bbox_units() const { return bbox_units_; }

    std::vector<GradientStop> stops() const {
        std::vector<GradientStop> stops;
        for (const pugi::xml_node& n : chain_) {
            for (const pugi::xml_node& s : n.children("stop")) stops.push_back(read_stop(cx_, s, stops));
            if (!stops.empty()) break;
        }
        return stops;
    }

    // gradientTransform about the origin of the gradient's units; a singular one is ignored.
    Affine transform() const {
        Affine gt;
        if (const std::string_view t = attr("gradientTransform", false); !t.empty()) {
            try {
                gt = parse_svg_transform(t);
                if (!gt.inverse()) gt = Affine{};
                gt = bbox_units_ ? with_origin(cx_, node_, gt, Viewport{1, 1}) : with_origin(cx_, node_, gt, vp_);
            } catch (const Error&) { warn(cx_, "invalid gradientTransform; ignored"); }
        }
        return gt;
    }

    SpreadMethod spread() const {
        const std::string_view sm = attr("spreadMethod", false);
        return sm == "reflect" ? SpreadMethod::Reflect : sm == "repeat" ? SpreadMethod::Repeat : SpreadMethod::Pad;
    }

    // A geometry attribute of this kind of gradient: a length (percentages of `percent_of` in user
    // space units, of 1 in bounding box units), or `fallback` when absent or invalid.
    double coord(const char* name, double percent_of, double fallback) const {
        const std::string_view v = attr(name, true);
        if (v.empty()) return fallback;
        auto l = parse_length(v, bbox_units_ ? 1.0 : percent_of, kUnknownFontSize, cx_.options.dpi);
        return l ? *l : fallback;
    }

private:
    std::string_view attr(const char* name, bool same_kind_only) const {
        for (const pugi::xml_node& n : chain_) {
            if (same_kind_only && std::string_view(n.name()) != kind_) continue;
            if (const char* v = n.attribute(name).value(); *v) return v;
        }
        return {};
    }

    Context& cx_;
    pugi::xml_node node_;
    Viewport vp_;
    std::vector<pugi::xml_node> chain_;
    std::string_view kind_;
    bool bbox_units_;
};

// The radial gradient's shader (circles in the gradient's units, mapped by `m`).
std::shared_ptr<const Shader> radial_shader(const GradientReader& g, Viewport vp, std::vector<GradientStop> stops,
                                            SpreadMethod spread, const Affine& m) {
    const bool bbox = g.bbox_units();
    const double diag = vp.diagonal();
    const double center_x = g.coord("cx", vp.w, bbox ? 0.5 : vp.w / 2),
                 center_y = g.coord("cy", vp.h, bbox ? 0.5 : vp.h / 2);
    // A negative radius is invalid and falls back to the default.
    double r = g.coord("r", diag, bbox ? 0.5 : diag / 2);
    if (r < 0) r = bbox ? 0.5 : diag / 2;
    const double fx = g.coord("fx", vp.w, center_x), fy = g.coord("fy", vp.h, center_y);
    double fr = std::max(0.0, g.coord("fr", diag, 0));
    if (r > 0 && std::fabs(fr - r) <= 1e-9 * r && fx == center_x && fy == center_y && spread == SpreadMethod::Pad) {
        // Equal circles around one centre leave no cone between them; as Skia and resvg draw it,
        // the first stop's colour fills the circle and the last one the rest (a hard stop at r).
        const Color first = stops.front().color, last = stops.back().color;
        stops = {{0, first}, {1, first}, {1, last}};
        fr = 0;
    }
    return std::make_shared<const Shader>(
        Shader::radial({center_x, center_y}, r, {fx, fy}, fr, std::move(stops), spread, m));
}

}  // namespace

bool gradient(Context& cx, const pugi::xml_node& node, const Path& path, Viewport vp, DisplayItem& it) {
    const GradientReader g(cx, node, vp);
    std::vector<GradientStop> stops = g.stops();
    if (stops.empty()) return false;  // no stops: painted as none
    if (stops.size() == 1) {
        it.color = stops.front().color;
        return true;
    }
    const Affine gt = g.transform();
    const SpreadMethod spread = g.spread();
    Affine units;
    if (g.bbox_units()) {
        const Rect b = path.bounds();
        if (!(b.width() > 0) || !(b.height() > 0)) return false;  // objectBoundingBox of a zero-size box
        units = Affine::translate(b.x0, b.y0) * Affine::scale(b.width(), b.height());
    }
    if (g.linear()) {
        const Point p0{g.coord("x1", vp.w, 0), g.coord("y1", vp.h, 0)};
        const Point p1{g.coord("x2", vp.w, g.bbox_units() ? 1.0 : vp.w), g.coord("y2", vp.h, 0)};
        it.shader = std::make_shared<const Shader>(Shader::linear(p0, p1, std::move(stops), spread, units * gt));
    } else {
        it.shader = radial_shader(g, vp, std::move(stops), spread, units * gt);
    }
    return true;
}

}  // namespace casteljau::svg
