// Formats stage, SVG conversion: SvgOptions::export_id, one element drawn alone. The walk of the
// tree goes only down the way from the root to that element, so the element gets its ancestors'
// transforms, viewports, inherited properties and group effects, as if every other element were
// removed; the element's own content is drawn whole. Everything else the conversion reads
// (references, the style sheets, ids) still comes from the whole document.
#include <algorithm>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "formats/svg/context.hpp"

namespace casteljau::svg {

namespace {

// The id asked for, without a leading '#'.
std::string_view export_id(const Context& cx) {
    std::string_view id = cx.options.export_id;
    if (!id.empty() && id.front() == '#') id.remove_prefix(1);
    return id;
}

bool on_path(const std::vector<pugi::xml_node>& path, const pugi::xml_node& n) {
    return std::find(path.begin(), path.end(), n) != path.end();
}

// The element drawn for `target`: the outermost text element around it when it is part of a
// text (a tspan or textPath is laid out with its whole text), else `target` itself.
pugi::xml_node drawn_element(const pugi::xml_node& target) {
    pugi::xml_node drawn = target;
    for (pugi::xml_node n = target; n && n.type() == pugi::node_element; n = n.parent())
        if (std::string_view(n.name()) == "text") drawn = n;
    return drawn;
}

}  // namespace

// Looks up the exported element (a leading '#' ignored) and sets cx.export_path to it and its
// ancestors; the root itself leaves the path empty (the whole document). Throws
// Error(InvalidData) when no element has the id; `source` names the input in that message.
void find_export_target(Context& cx, const pugi::xml_node& root, std::string_view source) {
    if (cx.options.export_id.empty()) return;
    const std::string_view id = export_id(cx);
    const pugi::xml_node target = lookup(cx, id);
    if (!target) {
        std::string message = "no element with id '" + std::string(id) + "'";
        if (!source.empty()) message += " in " + std::string(source);
        throw Error(ErrorKind::InvalidData, message);
    }
    const pugi::xml_node drawn = drawn_element(target);
    if (drawn == root) return;
    for (pugi::xml_node n = drawn; n && n.type() == pugi::node_element; n = n.parent()) cx.export_path.push_back(n);
}

// Draws `child` of `parent` while an element is exported: the exported element whole, an
// ancestor of it as the way down to it, any other child of an ancestor not at all. Children of
// elements off the way (content that clips, masks, patterns and use elements draw) are drawn.
void export_child(Context& cx, const pugi::xml_node& parent, const pugi::xml_node& child, const Style& st,
                  const Affine& m, Viewport vp, int depth) {
    if (!on_path(cx.export_path, parent)) return element(cx, child, st, m, vp, depth);
    if (child == cx.export_path.front()) {
        std::vector<pugi::xml_node> path;
        path.swap(cx.export_path);  // the element's own content is drawn whole
        cx.export_reached = true;
        element(cx, child, st, m, vp, depth);
        cx.export_path.swap(path);
        return;
    }
    if (on_path(cx.export_path, child)) element(cx, child, st, m, vp, depth);
}

// A warning when the exported element lies where the walk never goes (defs, a clipPath, a
// mask, a pattern, a marker, a symbol, a hidden group): nothing of it is drawn.
void warn_export_not_reached(Context& cx) {
    if (cx.export_path.empty() || cx.export_reached) return;
    warn(cx, "the element with id '" + std::string(export_id(cx)) +
                 "' is not drawn where it stands in the document; nothing is drawn");
}

}  // namespace casteljau::svg
