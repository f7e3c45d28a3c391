// Formats stage, SVG conversion: the use element: instancing an element, a symbol or an svg, with
// reference-cycle checks and the context element of context-fill and context-stroke.
#include "formats/svg/context.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace casteljau::svg {

void use(Context& cx, const pugi::xml_node& u, const Style& st, const Affine& m, Viewport vp, int depth) {
    const char* h = href(u);
    const pugi::xml_node target = *h == '#' ? lookup(cx, h + 1) : pugi::xml_node();
    if (!target) {
        if (*h) warn(cx, std::string("<use> target '") + h + "' not found; skipped");
        return;
    }
    // A cycle: the target is the use itself or one of its ancestors, or contains a use being
    // expanded.
    for (pugi::xml_node a = u; a; a = a.parent())
        if (a == target) {
            warn(cx, std::string("<use> '") + h + "' references itself; skipped");
            return;
        }
    for (const pugi::xml_node& active : cx.use_stack)
        for (pugi::xml_node a = active; a; a = a.parent())
            if (a == target) {
                warn(cx, std::string("<use> '") + h + "' is part of a reference cycle; skipped");
                return;
            }
    const double x = length_attr(cx, u, "x", vp.w), y = length_attr(cx, u, "y", vp.h);
    cx.use_stack.push_back(u);
    Style ust = st;
    ust.context_fill = st.fill;
    ust.context_stroke = st.stroke;
    if (cx.measuring_use) {
        // Only geometry counts while measuring: context paint servers become solid.
        if (ust.context_fill.kind == PaintRef::Server) ust.context_fill = PaintRef::solid(Color::black());
        if (ust.context_stroke.kind == PaintRef::Server) ust.context_stroke = PaintRef::solid(Color::black());
    }
    const std::string_view tn = target.name();
    const bool instance = tn == "symbol" || tn == "svg";
    if (!cx.measuring_use && ((st.fill.kind == PaintRef::Server && !st.fill.context) ||
                              (st.stroke.kind == PaintRef::Server && !st.stroke.context))) {
        // The use element is the context element of context-fill and context-stroke: a paint
        // server is resolved for its bounding box, in its user space (with x and y for an
        // element; the use's own for a symbol or svg). The box is that of the content, taken
        // from a first pass with solid context paints whose items are then dropped. Uses
        // inside that pass are not measured themselves (only geometry matters there), so
        // nested uses cost one extra pass each, not a doubling per level; the pass's elements
        // count towards the expansion limit.
        auto context = std::make_shared<ContextElement>();
        context->transform = instance ? m : m * Affine::translate(x, y);
        context->viewport = vp;
        const std::size_t first = cx.items.size(), warned = cx.warnings.size(), text_before = cx.text_chars_total;
        Style probe = st;
        probe.fill = probe.stroke = PaintRef::solid(Color::black());
        cx.use_stack.pop_back();
        cx.measuring_use = true;
        try {
            use(cx, u, probe, m, vp, depth);
        } catch (...) {
            cx.measuring_use = false;
            throw;
        }
        cx.measuring_use = false;
        cx.use_stack.push_back(u);
        if (const std::optional<Rect> box = items_bbox(cx, first, context->transform)) context->path.add_rect(*box);
        cx.items.resize(first);
        cx.warnings.resize(warned);
        cx.text_chars_total = text_before;
        ust.context_fill = context_paint(st.fill, context);
        ust.context_stroke = context_paint(st.stroke, context);
    }
    if (instance) {
        const pugi::xml_node size_from = u.attribute("width") ? u : target;
        const pugi::xml_node hsize_from = u.attribute("height") ? u : target;
        const double w = length_attr(cx, size_from, "width", vp.w, vp.w);
        const double hh = length_attr(cx, hsize_from, "height", vp.h, vp.h);
        const double tx = tn == "svg" ? length_attr(cx, target, "x", vp.w) : 0,
                     ty = tn == "svg" ? length_attr(cx, target, "y", vp.h) : 0;
        Style tst = ust;
        apply_style(cx, target, tst);
        // The instanced symbol or svg keeps its own opacity.
        double op = 1;
        for (const auto& [k, v] : properties(cx, target))
            if (k == "opacity")
                if (auto o = parse_opacity(v)) op = *o;
        if (op < 1) cx.items.push_back(layer_item(DisplayItem::BeginLayer, op));
        viewport(cx, target, tst, m, x + tx, y + ty, w, hh, depth + 1, tn == "symbol");
        if (op < 1) cx.items.push_back(layer_item(DisplayItem::EndLayer, op));
    } else {
        element(cx, target, ust, m * Affine::translate(x, y), vp, depth + 1);
    }
    cx.use_stack.pop_back();
}

}  // namespace casteljau::svg
