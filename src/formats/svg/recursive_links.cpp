// Formats stage, SVG conversion: reference cycles through masks cut before conversion. A mask
// whose content (or the mask itself) names the mask again, directly or through one other mask,
// would recurse without end. Such a reference is replaced by `none`, scanning masks in document
// order, so the rest of the content is still drawn: the resvg test suite's references draw
// recursive masks that way (the specifications call the document in error and leave the
// rendering open). Other cycles are checked while converting (Context::active_refs).
#include <cstddef>
#include <string>
#include <string_view>

#include "formats/svg/context.hpp"

namespace casteljau::svg {

namespace {

// Work allowed for the scan (elements visited): a bound on documents with many large masks;
// past it the remaining cycles are left to the checks made while converting.
constexpr std::size_t kMaxLinkScan = 4'000'000;

// The element that `value` (url(#id)) names.
pugi::xml_node linked(const Context& cx, std::string_view value) {
    value = trim(value);
    if (value.substr(0, 5) != "url(#") return {};
    const std::size_t close = value.find(')');
    if (close == std::string_view::npos) return {};
    std::string_view id = trim(value.substr(5, close - 5));
    return lookup(cx, id);
}

// The element that `n`'s property `name` names (the cascaded value).
pugi::xml_node link_of(Context& cx, const pugi::xml_node& n, const std::string& name) {
    std::string value;
    for (const auto& [k, v] : properties(cx, n))
        if (k == name) value = v;
    return value.empty() ? pugi::xml_node() : linked(cx, value);
}

// Calls `f` on `top` and each of its descendant elements, in document order.
template <class F>
void each_element(const pugi::xml_node& top, std::size_t& work, F&& f) {
    for (pugi::xml_node n = top; n;) {
        if (++work > kMaxLinkScan) return;
        if (n.type() == pugi::node_element) f(n);
        if (pugi::xml_node c = n.first_child(); c) {
            n = c;
            continue;
        }
        while (n && n != top && !n.next_sibling()) n = n.parent();
        if (!n || n == top) return;
        n = n.next_sibling();
    }
}

// For each element of kind `kind` (in document order): a reference `name` back to it from
// itself or its content, or from the content of the element that content names, becomes none.
void cut_links(Context& cx, const pugi::xml_node& root, std::string_view kind, const std::string& name) {
    std::size_t work = 0;
    each_element(root, work, [&](const pugi::xml_node& owner) {
        if (std::string_view(owner.name()) != kind) return;
        each_element(owner, work, [&](const pugi::xml_node& d) {
            const pugi::xml_node link = link_of(cx, d, name);
            if (!link) return;
            if (link == owner) {
                override_property(cx, d, name, "none");
                return;
            }
            each_element(link, work, [&](const pugi::xml_node& d2) {
                if (link_of(cx, d2, name) == owner) override_property(cx, d2, name, "none");
            });
        });
    });
}

}  // namespace

void cut_recursive_links(Context& cx, const pugi::xml_node& root) { cut_links(cx, root, "mask", "mask"); }

}  // namespace casteljau::svg
