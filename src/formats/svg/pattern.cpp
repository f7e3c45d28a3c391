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

namespace {

// A pattern with its href chain: attributes come from the first element that has them, content
// from the first with child elements.
class PatternChain {
public:
    PatternChain(Context& cx, const pugi::xml_node& node)
        : chain_(href_chain(node, [&](std::string_view id) { return lookup(cx, id); }, {"pattern"})) {}

    std::string_view attr(const char* name) const {
        const pugi::xml_node n = first_with(name);
        return n ? n.attribute(name).value() : std::string_view{};
    }
    pugi::xml_node first_with(const char* name) const {
        for (const pugi::xml_node& n : chain_)
            if (*n.attribute(name).value()) return n;
        return {};
    }
    pugi::xml_node content() const {
        for (const pugi::xml_node& n : chain_)
            for (const pugi::xml_node& c : n.children())
                if (c.type() == pugi::node_element) return n;
        return {};
    }

private:
    std::vector<pugi::xml_node> chain_;
};

// The tile in user space: x, y, width and height in the pattern's units (fractions of the box `b`
// for objectBoundingBox, else lengths with percentages of the viewport); missing or invalid
// values are 0.
Rect tile_rect(Context& cx, const PatternChain& p, bool units_bbox, const Rect& b, Viewport vp) {
    auto num = [&](const char* name, double percent_of) -> double {
        const std::string_view v = p.attr(name);
        if (v.empty()) return 0;
        auto l = parse_length(v, units_bbox ? 1.0 : percent_of, kUnknownFontSize, cx.options.dpi);
        return l ? *l : 0;
    };
    if (units_bbox)
        return Rect::from_xywh(b.x0 + num("x", 1) * b.width(), b.y0 + num("y", 1) * b.height(),
                               num("width", 1) * b.width(), num("height", 1) * b.height());
    return Rect::from_xywh(num("x", vp.w), num("y", vp.h), num("width", vp.w), num("height", vp.h));
}

// patternTransform about its origin; a singular or invalid one is ignored.
Affine pattern_transform(Context& cx, const pugi::xml_node& node, const PatternChain& p, Viewport vp) {
    Affine pt;
    if (const std::string_view t = p.attr("patternTransform"); !t.empty()) {
        try {
            pt = parse_svg_transform(t);
            if (!pt.inverse()) pt = Affine{};
            pt = with_origin(cx, node, pt, vp);
        } catch (const Error&) { warn(cx, "invalid patternTransform; ignored"); }
    }
    return pt;
}

// The tile content's map to user space (its origin at the tile's corner, through the viewBox when
// there is one, else scaled by the box for objectBoundingBox content units) and its viewport.
Affine content_transform(const PatternChain& p, const Rect& tile, bool content_bbox, const Rect& b, Viewport& vp) {
    const pugi::xml_node vb_node = p.first_with("viewBox");
    if (auto vb = vb_node ? parse_viewbox(vb_node.attribute("viewBox").value()) : std::nullopt) {
        vp = {vb->width(), vb->height()};
        return Affine::translate(tile.x0, tile.y0) *
               viewbox_transform(*vb, vb_node.attribute("preserveAspectRatio").value(), tile.width(), tile.height());
    }
    const Affine cm = Affine::translate(tile.x0, tile.y0);
    return content_bbox ? cm * Affine::scale(b.width(), b.height()) : cm;
}

// The display items of the tile's content (the pattern and its content element marked active
// while they are converted, so that a pattern painting itself is cut off).
DisplayList tile_items(Context& cx, const pugi::xml_node& node, const pugi::xml_node& content, const Affine& cm,
                       Viewport vp) {
    if (++cx.paint_depth > cx.limits.nesting_depth)
        throw Error(ErrorKind::Limit, "patterns nested deeper than " + std::to_string(cx.limits.nesting_depth));
    DisplayList saved;
    std::swap(saved, cx.items);
    cx.active_refs.push_back(node);
    cx.active_refs.push_back(content);
    Style st;
    apply_style(cx, content, st);
    try {
        walk(cx, content, st, cm, vp, 1);
    } catch (...) {
        std::swap(saved, cx.items);
        throw;
    }
    cx.active_refs.pop_back();
    cx.active_refs.pop_back();
    --cx.paint_depth;
    std::swap(saved, cx.items);
    return saved;
}

}  // namespace

// A pattern's tile content becomes a PatternTile that the renderer draws at device resolution
// and repeats through an image shader.
bool pattern(Context& cx, const pugi::xml_node& node, const Path& path, Viewport vp, DisplayItem& it) {
    const PatternChain p(cx, node);
    const pugi::xml_node content = p.content();
    if (!content || is_active(cx, node) || is_active(cx, content)) return false;
    const bool units_bbox = p.attr("patternUnits") != "userSpaceOnUse";
    const bool content_bbox = p.attr("patternContentUnits") == "objectBoundingBox";
    const Rect b = path.bounds();
    const bool have_box = b.width() > 0 && b.height() > 0;
    if ((units_bbox || content_bbox) && !have_box) return false;
    const Rect tile = tile_rect(cx, p, units_bbox, b, vp);
    if (!(tile.width() > 0) || !(tile.height() > 0) || !std::isfinite(tile.width()) || !std::isfinite(tile.height()))
        return false;
    const Affine pt = pattern_transform(cx, node, p, vp);
    Viewport content_vp = vp;
    const Affine cm = content_transform(p, tile, content_bbox, b, content_vp);
    auto tile_content = std::make_shared<PatternTile>();
    tile_content->items = tile_items(cx, node, content, cm, content_vp);
    tile_content->tile = tile;
    tile_content->transform = pt;
    it.pattern = std::move(tile_content);
    return true;
}

}  // namespace casteljau::svg
