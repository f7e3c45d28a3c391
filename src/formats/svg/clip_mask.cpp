// Formats stage, SVG conversion: clipPath and mask content converted into mask layers.
#include "formats/svg/context.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "formats/svg/text_properties.hpp"
#include "formats/svg/text_layout.hpp"

namespace casteljau::svg {

// A clipPath's children drawn as opaque coverage into a mask layer that multiplies the
// enclosing layer. clipPathUnits objectBoundingBox maps 0..1 onto `box`.
void emit_clip(Context& cx, const pugi::xml_node& clip, const Affine& cm, const std::optional<Rect>& box, Viewport vp,
               int depth) {
    cx.active_refs.push_back(clip);
    DisplayItem begin;
    begin.kind = DisplayItem::BeginClip;
    cx.items.push_back(std::move(begin));
    Affine m = cm;
    bool ok = true;
    if (const char* t = clip.attribute("transform").value(); *t) {
        try {
            m = m * with_origin(cx, clip, parse_svg_transform(t), vp);
        } catch (const Error&) {
            ok = false;  // an invalid transform clips everything away
        }
    }
    if (std::string_view(clip.attribute("clipPathUnits").value()) == "objectBoundingBox") {
        if (!box || !(box->width() > 0) || !(box->height() > 0))
            ok = false;
        else
            m = m * Affine::translate(box->x0, box->y0) * Affine::scale(box->width(), box->height());
    }
    bool inner_missing = false;
    pugi::xml_node inner = reference(cx, clip, "clip-path", "clipPath", inner_missing);
    if (inner && is_active(cx, inner)) inner = {};  // a reference back into the cycle is ignored (as resvg does)
    if (ok) {
        if (inner) cx.items.push_back(layer_item(DisplayItem::BeginLayer, 1));
        // clip-rule is inherited: the clipPath's own value, or its ancestors'.
        const FillRule rule = inherited(cx, clip, "clip-rule") == "evenodd" ? FillRule::EvenOdd : FillRule::NonZero;
        for (const pugi::xml_node& c : clip.children())
            if (c.type() == pugi::node_element) clip_child(cx, c, m, rule, vp, depth + 1);
        if (inner) {
            emit_clip(cx, inner, cm, box, vp, depth + 1);
            cx.items.push_back(layer_item(DisplayItem::EndLayer, 1));
        }
    }
    DisplayItem end;
    end.kind = DisplayItem::EndMask;
    cx.items.push_back(std::move(end));
    cx.active_refs.pop_back();
}

namespace {

// A black fill of `path` with `rule` mapped by `cm`: one clip shape.
DisplayItem clip_fill(Path path, FillRule rule, const Affine& cm) {
    DisplayItem it;
    it.kind = DisplayItem::Fill;
    it.color = Color::black();
    it.rule = rule;
    it.transform = cm;
    it.path = std::move(path);
    return it;
}

// Whether a clipPath child is drawn (display and visibility), its clip-rule read into `rule`.
bool clip_child_shown(Context& cx, const pugi::xml_node& c, FillRule& rule) {
    bool visible = true;
    for (const auto& [k, v] : properties(cx, c)) {
        const std::string_view val = trim(v);
        if (k == "display" && val == "none") return false;
        if (k == "visibility") visible = val == "visible";
        if (k == "clip-rule") rule = val == "evenodd" ? FillRule::EvenOdd : FillRule::NonZero;
    }
    return visible;
}

// A use inside a clipPath: only a shape or text may be its target, placed at the use's x and y.
void clip_use(Context& cx, const pugi::xml_node& c, const Affine& cm, FillRule rule, Viewport vp, int depth) {
    const char* h = href(c);
    const pugi::xml_node target = *h == '#' ? lookup(cx, h + 1) : pugi::xml_node();
    if (!target || is_active(cx, target)) return;
    const std::string_view tn = target.name();
    if (tn != "path" && tn != "rect" && tn != "circle" && tn != "ellipse" && tn != "polyline" && tn != "polygon" &&
        tn != "text")
        return;
    cx.active_refs.push_back(target);
    const Affine at = Affine::translate(length_attr(cx, c, "x", vp.w), length_attr(cx, c, "y", vp.h));
    clip_child(cx, target, cm * at, rule, vp, depth + 1);
    cx.active_refs.pop_back();
}

// Text inside a clipPath: its glyph outlines (and decorations), filled black.
void clip_text(Context& cx, const pugi::xml_node& c, const Affine& cm, FillRule rule, Viewport vp) {
    std::vector<Style> styles;
    for (svg_text::Outline& o : text_outlines(cx, c, Style{}, vp, styles)) {
        if (o.layer == svg_text::Outline::Glyphs && o.path.empty()) continue;
        cx.items.push_back(clip_fill(std::move(o.path), rule, cm));
    }
}

// A shape inside a clipPath (not a line, which has no area), clipped by its own clip-path.
void clip_shape(Context& cx, const pugi::xml_node& c, const Affine& cm, FillRule rule, Viewport vp, int depth) {
    std::optional<Path> p = shape_path(cx, c, vp);
    if (!p || p->empty() || std::string_view(c.name()) == "line") return;
    bool missing = false;
    pugi::xml_node own = reference(cx, c, "clip-path", "clipPath", missing);
    if (own && is_active(cx, own)) own = {};  // a reference back into the cycle is ignored (as resvg does)
    if (own) cx.items.push_back(layer_item(DisplayItem::BeginLayer, 1));
    const Rect b = p->bounds();
    cx.items.push_back(clip_fill(std::move(*p), rule, cm));
    if (own) {
        emit_clip(cx, own, cm, b, vp, depth + 1);
        cx.items.push_back(layer_item(DisplayItem::EndLayer, 1));
    }
}

}  // namespace

// One child of a clipPath: a shape (or a use of a shape), its own transform, clip-rule and
// clip-path; fill, stroke and opacity have no effect.
void clip_child(Context& cx, const pugi::xml_node& c, const Affine& m, FillRule rule, Viewport vp, int depth) {
    if (depth > cx.limits.nesting_depth)
        throw Error(ErrorKind::Limit, "SVG elements nested deeper than " + std::to_string(cx.limits.nesting_depth));
    if (++cx.expanded > cx.limits.svg_elements)
        throw Error(ErrorKind::Limit,
                    "SVG expands to more than " + std::to_string(cx.limits.svg_elements) + " elements");
    if (!conditions_pass(c) || !clip_child_shown(cx, c, rule)) return;
    const Affine cm = m * element_transform(cx, c, vp);
    const std::string_view name = c.name();
    if (name == "use")
        clip_use(cx, c, cm, rule, vp, depth);
    else if (name == "text")
        clip_text(cx, c, cm, rule, vp);
    else
        clip_shape(cx, c, cm, rule, vp, depth);
}

// A mask's content drawn into a mask layer (luminance, or alpha with mask-type="alpha"),
// clipped to the mask region, that multiplies the enclosing layer.
void emit_mask(Context& cx, const pugi::xml_node& mask, const Affine& cm, const std::optional<Rect>& box, Viewport vp,
               int depth) {
    cx.active_refs.push_back(mask);
    DisplayItem begin;
    begin.kind = DisplayItem::BeginMask;
    std::string type;
    for (const auto& [k, v] : properties(cx, mask))
        if (k == "mask-type") type = std::string(trim(v));
    begin.luminance = type != "alpha";
    cx.items.push_back(std::move(begin));
    const bool bbox_units = std::string_view(mask.attribute("maskUnits").value()) != "userSpaceOnUse";
    const bool content_bbox = std::string_view(mask.attribute("maskContentUnits").value()) == "objectBoundingBox";
    const bool have_box = box && box->width() > 0 && box->height() > 0;
    if (have_box || (!bbox_units && !content_bbox)) {
        Rect region;
        auto frac = [&](const char* name, double fallback) {
            const char* v = mask.attribute(name).value();
            if (!*v) return fallback;
            auto l = parse_length(v, 1.0, kUnknownFontSize, cx.options.dpi);
            return l ? *l : fallback;
        };
        if (bbox_units) {
            region =
                Rect::from_xywh(box->x0 + frac("x", -0.1) * box->width(), box->y0 + frac("y", -0.1) * box->height(),
                                frac("width", 1.2) * box->width(), frac("height", 1.2) * box->height());
        } else {
            region = Rect::from_xywh(
                length_attr(cx, mask, "x", vp.w, -0.1 * vp.w), length_attr(cx, mask, "y", vp.h, -0.1 * vp.h),
                length_attr(cx, mask, "width", vp.w, 1.2 * vp.w), length_attr(cx, mask, "height", vp.h, 1.2 * vp.h));
        }
        if (region.width() > 0 && region.height() > 0) {
            Affine content_m = cm;
            if (content_bbox)
                content_m = cm * Affine::translate(box->x0, box->y0) * Affine::scale(box->width(), box->height());
            bool inner_missing = false;
            const pugi::xml_node inner = reference(cx, mask, "mask", "mask", inner_missing);
            const bool inner_ok = inner && !is_active(cx, inner);
            clipped(cx, region, cm, [&] {
                if (inner_ok) cx.items.push_back(layer_item(DisplayItem::BeginLayer, 1));
                Style st;
                walk(cx, mask, st, content_m, vp, depth + 1);
                if (inner_ok) {
                    emit_mask(cx, inner, cm, box, vp, depth + 1);
                    cx.items.push_back(layer_item(DisplayItem::EndLayer, 1));
                }
            });
        }
    }
    DisplayItem end;
    end.kind = DisplayItem::EndMask;
    cx.items.push_back(std::move(end));
    cx.active_refs.pop_back();
}

}  // namespace casteljau::svg
