// Formats stage, SVG conversion: the pattern paint server: its tile content converted into a
// PatternTile.
#include "formats/svg/context.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace casteljau::svg {

// A pattern with its href chain (attributes from the first element that has them, content
// from the first with child elements): its tile content becomes a PatternTile that the
// renderer draws at device resolution and repeats through an image shader.
bool pattern(Context& cx, const pugi::xml_node& node, const Path& path, Viewport vp, DisplayItem& it) {
    const std::vector<pugi::xml_node> chain =
        href_chain(node, [&](std::string_view id) { return lookup(cx, id); }, {"pattern"});
    auto attr = [&](const char* name) -> std::string_view {
        for (const pugi::xml_node& n : chain)
            if (const char* v = n.attribute(name).value(); *v) return v;
        return {};
    };
    pugi::xml_node content;
    for (const pugi::xml_node& n : chain) {
        for (const pugi::xml_node& c : n.children())
            if (c.type() == pugi::node_element) {
                content = n;
                break;
            }
        if (content) break;
    }
    if (!content || is_active(cx, node) || is_active(cx, content)) return false;
    const bool units_bbox = attr("patternUnits") != "userSpaceOnUse";
    const bool content_bbox = attr("patternContentUnits") == "objectBoundingBox";
    const Rect b = path.bounds();
    const bool have_box = b.width() > 0 && b.height() > 0;
    if ((units_bbox || content_bbox) && !have_box) return false;
    auto num = [&](const char* name, double percent_of) -> double {
        const std::string_view v = attr(name);
        if (v.empty()) return 0;
        auto l = parse_length(v, units_bbox ? 1.0 : percent_of, kUnknownFontSize, cx.options.dpi);
        return l ? *l : 0;
    };
    Rect tile;
    if (units_bbox)
        tile = Rect::from_xywh(b.x0 + num("x", 1) * b.width(), b.y0 + num("y", 1) * b.height(),
                               num("width", 1) * b.width(), num("height", 1) * b.height());
    else
        tile = Rect::from_xywh(num("x", vp.w), num("y", vp.h), num("width", vp.w), num("height", vp.h));
    if (!(tile.width() > 0) || !(tile.height() > 0) || !std::isfinite(tile.width()) || !std::isfinite(tile.height()))
        return false;
    Affine pt;
    if (const std::string_view t = attr("patternTransform"); !t.empty()) {
        try {
            pt = parse_svg_transform(t);
            if (!pt.inverse()) pt = Affine{};  // a singular patternTransform is ignored
            pt = with_origin(cx, node, pt, vp);
        } catch (const Error&) { warn(cx, "invalid patternTransform; ignored"); }
    }
    Affine cm;
    Viewport content_vp = vp;
    const pugi::xml_node vb_node = [&] {
        for (const pugi::xml_node& n : chain)
            if (*n.attribute("viewBox").value()) return n;
        return pugi::xml_node();
    }();
    if (auto vb = vb_node ? parse_viewbox(vb_node.attribute("viewBox").value()) : std::nullopt) {
        cm = Affine::translate(tile.x0, tile.y0) *
             viewbox_transform(*vb, vb_node.attribute("preserveAspectRatio").value(), tile.width(), tile.height());
        content_vp = {vb->width(), vb->height()};
    } else {
        // The content's origin is the tile's top-left corner.
        cm = Affine::translate(tile.x0, tile.y0);
        if (content_bbox) cm = cm * Affine::scale(b.width(), b.height());
    }
    if (++cx.paint_depth > cx.limits.nesting_depth)
        throw Error(ErrorKind::Limit, "patterns nested deeper than " + std::to_string(cx.limits.nesting_depth));
    DisplayList saved;
    std::swap(saved, cx.items);
    cx.active_refs.push_back(node);
    cx.active_refs.push_back(content);
    Style st;
    apply_style(cx, content, st);
    try {
        walk(cx, content, st, cm, content_vp, 1);
    } catch (...) {
        std::swap(saved, cx.items);
        throw;
    }
    cx.active_refs.pop_back();
    cx.active_refs.pop_back();
    --cx.paint_depth;
    auto tile_items = std::make_shared<PatternTile>();
    tile_items->items = std::move(cx.items);
    tile_items->tile = tile;
    tile_items->transform = pt;
    cx.items = std::move(saved);
    it.pattern = std::move(tile_items);
    return true;
}

}  // namespace casteljau::svg
