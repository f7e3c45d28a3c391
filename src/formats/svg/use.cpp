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

namespace {

// Whether `target` is the use `u` itself or one of its ancestors, or contains a use being
// expanded (warned, with the use's href `h`).
bool in_cycle(Context& cx, const pugi::xml_node& u, const pugi::xml_node& target, const char* h) {
    for (pugi::xml_node a = u; a; a = a.parent())
        if (a == target) {
            warn(cx, std::string("<use> '") + h + "' references itself; skipped");
            return true;
        }
    for (const pugi::xml_node& active : cx.use_stack)
        for (pugi::xml_node a = active; a; a = a.parent())
            if (a == target) {
                warn(cx, std::string("<use> '") + h + "' is part of a reference cycle; skipped");
                return true;
            }
    return false;
}

// The use element as the context element of context-fill and context-stroke when its paint is a
// server: the server is resolved for the box of the content (in `transform`, the use's user
// space), which a first pass with solid context paints measures; that pass's items, warnings and
// text count are then dropped. Uses inside the pass are not measured themselves (only geometry
// matters there), so nested uses cost one extra pass each, not a doubling per level; the pass's
// elements count towards the expansion limit.
std::shared_ptr<ContextElement> measured_context(Context& cx, const pugi::xml_node& u, const Style& st, const Affine& m,
                                                 Viewport vp, int depth, const Affine& transform) {
    auto context = std::make_shared<ContextElement>();
    context->transform = transform;
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
    return context;
}

// A symbol or an svg instanced at (x, y): its size from the use's width and height, else its
// own; its own opacity kept as a layer.
void instance(Context& cx, const pugi::xml_node& u, const pugi::xml_node& target, const Style& ust, const Affine& m,
              double x, double y, Viewport vp, int depth) {
    const std::string_view tn = target.name();
    const pugi::xml_node size_from = u.attribute("width") ? u : target;
    const pugi::xml_node hsize_from = u.attribute("height") ? u : target;
    const double w = length_attr(cx, size_from, "width", vp.w, vp.w);
    const double hh = length_attr(cx, hsize_from, "height", vp.h, vp.h);
    const double tx = tn == "svg" ? length_attr(cx, target, "x", vp.w) : 0,
                 ty = tn == "svg" ? length_attr(cx, target, "y", vp.h) : 0;
    Style tst = ust;
    apply_style(cx, target, tst);
    double op = 1;
    for (const auto& [k, v] : properties(cx, target))
        if (k == "opacity")
            if (auto o = parse_opacity(v)) op = *o;
    if (op < 1) cx.items.push_back(layer_item(DisplayItem::BeginLayer, op));
    viewport(cx, target, tst, m, x + tx, y + ty, w, hh, depth + 1, tn == "symbol");
    if (op < 1) cx.items.push_back(layer_item(DisplayItem::EndLayer, op));
}

}  // namespace

void use(Context& cx, const pugi::xml_node& u, const Style& st, const Affine& m, Viewport vp, int depth) {
    const char* h = href(u);
    const pugi::xml_node target = *h == '#' ? lookup(cx, h + 1) : pugi::xml_node();
    if (!target) {
        if (*h) warn(cx, std::string("<use> target '") + h + "' not found; skipped");
        return;
    }
    if (in_cycle(cx, u, target, h)) return;
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
    const bool is_instance = tn == "symbol" || tn == "svg";
    if (!cx.measuring_use && ((st.fill.kind == PaintRef::Server && !st.fill.context) ||
                              (st.stroke.kind == PaintRef::Server && !st.stroke.context))) {
        // In the use's user space: with x and y for an element, the use's own for a symbol or svg.
        const auto context = measured_context(cx, u, st, m, vp, depth, is_instance ? m : m * Affine::translate(x, y));
        ust.context_fill = context_paint(st.fill, context);
        ust.context_stroke = context_paint(st.stroke, context);
    }
    if (is_instance)
        instance(cx, u, target, ust, m, x, y, vp, depth);
    else
        element(cx, target, ust, m * Affine::translate(x, y), vp, depth + 1);
    cx.use_stack.pop_back();
}

}  // namespace casteljau::svg
