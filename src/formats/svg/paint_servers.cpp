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

// A linearGradient or radialGradient with its href chain: attributes come from the first
// element of the chain that has them, stops from the first that has any.
bool gradient(Context& cx, const pugi::xml_node& node, const Path& path, Viewport vp, DisplayItem& it) {
    const std::vector<pugi::xml_node> chain =
        href_chain(node, [&](std::string_view id) { return lookup(cx, id); }, {"linearGradient", "radialGradient"});
    const std::string_view kind = node.name();
    auto attr = [&](const char* name, bool same_kind_only) -> std::string_view {
        for (const pugi::xml_node& n : chain) {
            if (same_kind_only && std::string_view(n.name()) != kind) continue;
            if (const char* v = n.attribute(name).value(); *v) return v;
        }
        return {};
    };
    // Stops.
    std::vector<GradientStop> stops;
    for (const pugi::xml_node& n : chain) {
        for (const pugi::xml_node& s : n.children("stop")) {
            GradientStop st;
            std::string_view off = trim(s.attribute("offset").value());
            double o = 0;
            if (!off.empty() && off.back() == '%') {
                if (auto v = parse_number(off.substr(0, off.size() - 1))) o = *v / 100;
            } else if (auto v = parse_number(off)) {
                o = *v;
            }
            st.offset = std::clamp(o, 0.0, 1.0);
            if (!stops.empty()) st.offset = std::max(st.offset, stops.back().offset);
            Color color = Color::black();
            double opacity = 1;
            for (const auto& [k, v] : properties(cx, s)) {
                std::string val(trim(v));
                // stop-color and stop-opacity are not inherited: `inherit` takes the parent's
                // own value, or the initial one.
                if (val == "inherit")
                    val = k == "stop-color" || k == "stop-opacity" ? own_property(cx, s.parent(), k) : "";
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
            stops.push_back(st);
        }
        if (!stops.empty()) break;
    }
    if (stops.empty()) return false;  // no stops: painted as none
    if (stops.size() == 1) {
        it.color = stops.front().color;
        return true;
    }
    const bool bbox_units = attr("gradientUnits", false) != "userSpaceOnUse";
    Affine gt;
    if (const std::string_view t = attr("gradientTransform", false); !t.empty()) {
        try {
            gt = parse_svg_transform(t);
            if (!gt.inverse()) gt = Affine{};  // a singular gradientTransform is ignored
            gt = bbox_units ? with_origin(cx, node, gt, Viewport{1, 1}) : with_origin(cx, node, gt, vp);
        } catch (const Error&) { warn(cx, "invalid gradientTransform; ignored"); }
    }
    SpreadMethod spread = SpreadMethod::Pad;
    if (const std::string_view sm = attr("spreadMethod", false); sm == "reflect")
        spread = SpreadMethod::Reflect;
    else if (sm == "repeat")
        spread = SpreadMethod::Repeat;
    const double diag = vp.diagonal();
    auto coord = [&](const char* name, double percent_of, double fallback) {
        const std::string_view v = attr(name, true);
        if (v.empty()) return fallback;
        auto l = parse_length(v, bbox_units ? 1.0 : percent_of, kUnknownFontSize, cx.options.dpi);
        return l ? *l : fallback;
    };
    Affine units;
    if (bbox_units) {
        const Rect b = path.bounds();
        if (!(b.width() > 0) || !(b.height() > 0)) return false;  // objectBoundingBox of a zero-size box
        units = Affine::translate(b.x0, b.y0) * Affine::scale(b.width(), b.height());
    }
    if (kind == "linearGradient") {
        const Point p0{coord("x1", vp.w, 0), coord("y1", vp.h, 0)};
        const Point p1{coord("x2", vp.w, bbox_units ? 1.0 : vp.w), coord("y2", vp.h, 0)};
        it.shader = std::make_shared<const Shader>(Shader::linear(p0, p1, std::move(stops), spread, units * gt));
        return true;
    }
    const double half_w = bbox_units ? 0.5 : vp.w / 2, half_h = bbox_units ? 0.5 : vp.h / 2;
    const double center_x = coord("cx", vp.w, half_w), center_y = coord("cy", vp.h, half_h);
    // A negative radius is invalid and falls back to the default.
    double r = coord("r", diag, bbox_units ? 0.5 : diag / 2);
    if (r < 0) r = bbox_units ? 0.5 : diag / 2;
    const double fx = coord("fx", vp.w, center_x), fy = coord("fy", vp.h, center_y);
    double fr = std::max(0.0, coord("fr", diag, 0));
    if (r > 0 && std::fabs(fr - r) <= 1e-9 * r && fx == center_x && fy == center_y && spread == SpreadMethod::Pad) {
        // Equal circles around one centre leave no cone between them; as Skia and resvg draw it,
        // the first stop's colour fills the circle and the last one the rest (a hard stop at r).
        const Color first = stops.front().color, last = stops.back().color;
        stops = {{0, first}, {1, first}, {1, last}};
        fr = 0;
    }
    it.shader = std::make_shared<const Shader>(
        Shader::radial({center_x, center_y}, r, {fx, fy}, fr, std::move(stops), spread, units * gt));
    return true;
}

}  // namespace casteljau::svg
