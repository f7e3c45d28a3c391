// Formats stage, SVG conversion: the element tree: containers, nested viewports, conditional
// processing, transforms, and what each element becomes (layers for opacity, clips, masks, filters
// and blending).
#include "formats/svg/context.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "formats/svg/filter_graphs.hpp"

namespace casteljau::svg {

void walk(Context& cx, const pugi::xml_node& node, const Style& st, const Affine& m, Viewport vp, int depth) {
    if (depth > cx.limits.nesting_depth)
        throw Error(ErrorKind::Limit, "SVG elements nested deeper than " + std::to_string(cx.limits.nesting_depth));
    const bool is_switch = std::string_view(node.name()) == "switch";
    for (const pugi::xml_node& child : node.children()) {
        if (child.type() != pugi::node_element) continue;
        if (!conditions_pass(child)) continue;
        if (cx.export_path.empty())
            element(cx, child, st, m, vp, depth);
        else
            export_child(cx, node, child, st, m, vp, depth);  // only the way to the exported element
        if (is_switch && known_element(child.name())) break;  // a switch draws its first passing child only
    }
}

bool known_element(std::string_view n) {
    return n == "g" || n == "a" || n == "switch" || n == "svg" || n == "use" || n == "path" || n == "rect" ||
           n == "circle" || n == "ellipse" || n == "line" || n == "polyline" || n == "polygon" || n == "image" ||
           n == "text" || n == "foreignObject";
}

// Conditional processing: systemLanguage (the user language is English), requiredExtensions
// (none supported); requiredFeatures is always true (SVG 2).
bool conditions_pass(const pugi::xml_node& n) {
    if (const pugi::xml_attribute ext = n.attribute("requiredExtensions"); ext) return false;
    if (const pugi::xml_attribute lang = n.attribute("systemLanguage"); lang) {
        std::string_view v = lang.value();
        bool any = false;
        while (!v.empty()) {
            const std::size_t comma = v.find(',');
            std::string_view l = trim(v.substr(0, comma));
            v = comma == std::string_view::npos ? std::string_view{} : v.substr(comma + 1);
            if (l == "en" || l.substr(0, 3) == "en-") any = true;
        }
        if (!any) return false;
    }
    return true;
}

// transform-origin ("x [y]": lengths, percentages of the viewport, or the keywords left,
// center, right, top, bottom in either order) wrapped around a transform `t`:
// translate(origin) * t * translate(-origin).
Affine with_origin(Context& cx, const pugi::xml_node& n, const Affine& t, Viewport vp) {
    std::string value;
    for (const auto& [k, v] : properties(cx, n))
        if (k == "transform-origin") value = std::string(trim(v));
    if (value.empty()) return t;
    std::vector<std::string> words;
    std::string w;
    for (char c : value + " ") {
        if (std::isspace(static_cast<unsigned char>(c)) || c == ',') {
            if (!w.empty()) words.push_back(w);
            w.clear();
        } else {
            w += c;
        }
    }
    if (words.empty() || words.size() > 3) return t;
    if (words.size() == 2 && (words[0] == "top" || words[0] == "bottom" || words[1] == "left" || words[1] == "right"))
        std::swap(words[0], words[1]);
    auto axis = [&](const std::string& word, double size, bool horizontal) -> double {
        if (word == "center") return size / 2;
        if (horizontal ? word == "left" : word == "top") return 0;
        if (horizontal ? word == "right" : word == "bottom") return size;
        auto l = parse_length(word, size, kUnknownFontSize, cx.options.dpi);
        return l ? *l : size / 2;
    };
    double ox, oy;
    if (words.size() == 1) {
        if (words[0] == "top" || words[0] == "bottom") {
            ox = vp.w / 2;
            oy = axis(words[0], vp.h, false);
        } else {
            ox = axis(words[0], vp.w, true);
            oy = vp.h / 2;
        }
    } else {
        ox = axis(words[0], vp.w, true);
        oy = axis(words[1], vp.h, false);
    }
    return Affine::translate(ox, oy) * t * Affine::translate(-ox, -oy);
}

// The transform of `n`, with its transform-origin: the last value of the transform property
// that parses (the CSS property of a style sheet or style attribute after the attribute); a
// value that does not parse is ignored with a warning, as browsers ignore it.
Affine element_transform(Context& cx, const pugi::xml_node& n, Viewport vp) {
    std::optional<Affine> t;
    for (const auto& [k, v] : properties(cx, n)) {
        if (k != "transform" || trim(v).empty()) continue;
        try {
            t = parse_svg_transform(v);
        } catch (const Error& e) { warn(cx, std::string("<") + n.name() + ">: " + e.what() + "; transform ignored"); }
    }
    return t ? with_origin(cx, n, *t, vp) : Affine::identity();
}

// A new viewport (nested svg, or a symbol or svg instanced by use) at x, y, w x h in the
// user space of `m`, with its viewBox and preserveAspectRatio; clipped unless overflow is
// visible or auto.
void viewport(Context& cx, const pugi::xml_node& n, const Style& st, const Affine& m, double x, double y, double w,
              double h, int depth, bool is_symbol) {
    if (!(w > 0) || !(h > 0)) return;
    Affine inner = m * Affine::translate(x, y);
    Viewport inner_vp{w, h};
    if (auto vb = parse_viewbox(n.attribute("viewBox").value())) {
        inner = inner * viewbox_transform(*vb, n.attribute("preserveAspectRatio").value(), w, h);
        inner_vp = {vb->width(), vb->height()};
    }
    if (is_symbol) {
        const double rx = length_attr(cx, n, "refX", inner_vp.w), ry = length_attr(cx, n, "refY", inner_vp.h);
        inner = inner * Affine::translate(-rx, -ry);
    }
    std::string overflow;
    for (const auto& [k, v] : properties(cx, n))
        if (k == "overflow") overflow = std::string(trim(v));
    auto draw = [&] { walk(cx, n, st, inner, inner_vp, depth + 1); };
    if (overflow == "visible" || overflow == "auto")
        draw();
    else
        clipped(cx, Rect::from_xywh(x, y, w, h), m, draw);
}

// Bounding box, in the user space of `m`, of the fills and strokes among items[first..]
// (leaving out the content of clips and masks); the path geometry, not the stroke outline.
std::optional<Rect> items_bbox(const Context& cx, std::size_t first, const Affine& m) {
    const auto inv = m.inverse();
    if (!inv) return std::nullopt;
    std::optional<Rect> box;
    int hidden = 0;
    for (std::size_t i = first; i < cx.items.size(); ++i) {
        const DisplayItem& it = cx.items[i];
        if (it.kind == DisplayItem::BeginClip || it.kind == DisplayItem::BeginMask)
            ++hidden;
        else if (it.kind == DisplayItem::EndMask)
            --hidden;
        else if (hidden == 0 &&
                 (it.kind == DisplayItem::Fill || it.kind == DisplayItem::Stroke || it.kind == DisplayItem::Bounds)) {
            const Rect b = transform_bounds(*inv * it.transform, it.path.bounds());
            box = box ? box->united(b) : b;
        }
    }
    return box;
}

namespace {

// Counts one more element against the nesting and expansion limits (Error(Limit) past them).
void count_element(Context& cx, int depth) {
    if (depth > cx.limits.nesting_depth)
        throw Error(ErrorKind::Limit, "SVG elements nested deeper than " + std::to_string(cx.limits.nesting_depth));
    if (++cx.expanded > cx.limits.svg_elements)
        throw Error(ErrorKind::Limit, "SVG expands to more than " + std::to_string(cx.limits.svg_elements) +
                                          " elements (nested <use> references)");
}

// Elements never drawn where they stand: definitions, resources referenced from elsewhere and
// text about the document.
bool drawn_by_reference_only(std::string_view name) {
    return name == "defs" || name == "title" || name == "desc" || name == "metadata" || name == "style" ||
           name == "clipPath" || name == "mask" || name == "pattern" || name == "linearGradient" ||
           name == "radialGradient" || name == "symbol" || name == "marker" || name == "filter";
}

double own_opacity(Context& cx, const pugi::xml_node& node) {
    double opacity = 1;
    for (const auto& [k, v] : properties(cx, node))
        if (k == "opacity")
            if (auto ov = parse_opacity(v)) opacity = *ov;
    return opacity;
}

// An element with opacity 0 is not drawn, but it still counts in its group's bounding box: its
// content's box, as a bounds item.
void bounds_only(Context& cx, const pugi::xml_node& node, const Style& cst, const Affine& cm, Viewport vp, int depth) {
    const std::size_t first = cx.items.size();
    content(cx, node, cst, cm, vp, depth, 1.0);
    const std::optional<Rect> box = items_bbox(cx, first, cm);
    cx.items.resize(first);
    if (box) cx.items.push_back(bounds_item(Path().add_rect(*box), cm));
}

}  // namespace

void element(Context& cx, const pugi::xml_node& child, const Style& st, const Affine& m, Viewport vp, int depth) {
    count_element(cx, depth);
    if (drawn_by_reference_only(child.name())) return;
    Style cst = st;
    cst.viewport = vp;
    apply_style(cx, child, cst);
    for (const auto& [k, v] : properties(cx, child))
        if (k == "display" && trim(v) == "none") return;
    const Affine cm = m * element_transform(cx, child, vp);
    const double opacity = own_opacity(cx, child);
    if (opacity <= 0) return bounds_only(cx, child, cst, cm, vp, depth);
    bool clip_missing = false, mask_missing = false;
    const pugi::xml_node clip = reference(cx, child, "clip-path", "clipPath", clip_missing);
    const pugi::xml_node mask = reference(cx, child, "mask", "mask", mask_missing);
    (void)clip_missing;  // a clip-path or mask naming nothing is ignored (as browsers do)
    (void)mask_missing;
    if ((clip && is_active(cx, clip)) || (mask && is_active(cx, mask))) {
        warn(cx, std::string("<") + child.name() + ">: recursive clip-path or mask; element not drawn");
        return;
    }
    BlendMode blend = BlendMode::Normal;
    bool isolate = false;
    for (const auto& [k, v] : properties(cx, child)) {
        if (k == "mix-blend-mode") parse_blend_mode(trim(v), blend);
        if (k == "isolation") isolate = trim(v) == "isolate";
    }
    const std::optional<ElementFilters> filters = element_filters(cx, child, cst, vp, depth);
    if (!filters) return;
    const bool filtered = filters->refs.has_value();
    const bool layered = opacity < 1 || clip || mask || blend != BlendMode::Normal || isolate || filtered;
    const std::size_t first = cx.items.size();
    if (layered) {
        DisplayItem begin = layer_item(DisplayItem::BeginLayer, opacity);
        begin.blend = blend;
        cx.items.push_back(std::move(begin));
    }
    const std::size_t filter_first = cx.items.size();
    if (filtered) cx.items.push_back(layer_item(DisplayItem::BeginFilter, 1));
    cx.active_refs.insert(cx.active_refs.end(), filters->nodes.begin(), filters->nodes.end());
    content(cx, child, cst, cm, vp, depth, layered ? 1.0 : opacity);
    cx.active_refs.resize(cx.active_refs.size() - filters->nodes.size());
    if (filtered && !finish_filters(cx, child, *filters, filter_first, cm, cst, vp, depth)) {
        cx.items.resize(first);
        return;
    }
    if (layered) {
        const std::optional<Rect> box = items_bbox(cx, first + 1, cm);
        if (clip) emit_clip(cx, clip, cm, box, vp, depth);
        if (mask) emit_mask(cx, mask, cm, box, vp, depth);
        cx.items.push_back(layer_item(DisplayItem::EndLayer, opacity));
    }
}

void content(Context& cx, const pugi::xml_node& child, const Style& cst, const Affine& cm, Viewport vp, int depth,
             double opacity) {
    const std::string_view name = child.name();
    const bool container = name == "g" || name == "a" || name == "switch" || name == "svg" || name == "use";
    if (container) {
        const bool layer = opacity < 1;
        if (layer) cx.items.push_back(layer_item(DisplayItem::BeginLayer, opacity));
        if (name == "svg" && child.parent() == child.root()) {
            // The root svg: its viewport is the document's, already set up by the caller.
            walk(cx, child, cst, cm, vp, depth + 1);
        } else if (name == "svg") {
            const double w = length_attr(cx, child, "width", vp.w, vp.w);
            const double h = length_attr(cx, child, "height", vp.h, vp.h);
            viewport(cx, child, cst, cm, length_attr(cx, child, "x", vp.w), length_attr(cx, child, "y", vp.h), w, h,
                     depth, false);
        } else if (name == "use") {
            use(cx, child, cst, cm, vp, depth);
        } else {
            walk(cx, child, cst, cm, vp, depth + 1);
        }
        if (layer) cx.items.push_back(layer_item(DisplayItem::EndLayer, opacity));
        return;
    }
    if (name == "image") return image(cx, child, cst, cm, vp, opacity);
    if (name == "text") return text(cx, child, cst, cm, vp, opacity);
    std::optional<Path> p = shape_path(cx, child, vp);
    if (!p) {
        if (name != "path" && name != "rect" && name != "circle" && name != "ellipse" && name != "line" &&
            name != "polyline" && name != "polygon")
            warn(cx, "<" + std::string(name) + "> is not supported; skipped");
        return;
    }
    if (p->empty()) return;
    if (!cst.visible) {
        // Hidden shapes are not drawn but still count in their group's bounding box.
        cx.items.push_back(bounds_item(std::move(*p), cm));
        return;
    }
    // A line has no interior; a polyline fills like a polygon (closed implicitly).
    std::optional<DisplayItem> fill_item, stroke_item;
    if (DisplayItem f; name != "line" && resolve_paint(cx, cst.fill, *p, cm, vp, f)) {
        f.kind = DisplayItem::Fill;
        f.path = *p;
        f.transform = cm;
        f.rule = cst.fill_rule;
        f.opacity = cst.fill_opacity * opacity;
        fill_item = std::move(f);
    }
    const Path path_copy = *p;
    if (DisplayItem st; cst.stroke_style.width > 0 && resolve_paint(cx, cst.stroke, *p, cm, vp, st)) {
        st.kind = DisplayItem::Stroke;
        st.stroke = cst.stroke_style;
        st.path = std::move(*p);
        st.transform = cm;
        st.opacity = cst.stroke_opacity * opacity;
        stroke_item = std::move(st);
    }
    // SVG 2 draws markers on every shape: a rect, circle or ellipse has the vertices of its path
    // (the corners, or the ends of its quarter arcs, starting at the right of a circle).
    const bool markable = name == "path" || name == "line" || name == "polyline" || name == "polygon" ||
                          name == "rect" || name == "circle" || name == "ellipse";
    for (int part : cst.paint_order) {
        if (part == 0 && fill_item) cx.items.push_back(std::move(*fill_item));
        if (part == 1 && stroke_item) cx.items.push_back(std::move(*stroke_item));
        if (part == 2 && markable) emit_markers(cx, path_copy, cst, cm, vp, depth);
    }
}

}  // namespace casteljau::svg
