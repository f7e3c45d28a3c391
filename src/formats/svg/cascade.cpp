// Formats stage, SVG conversion: the CSS cascade of an element (presentation attributes, style
// sheets, the style attribute), computed font sizes, ids and references.
#include "formats/svg/context.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "formats/svg/text_properties.hpp"

namespace casteljau::svg {

// Records a warning for the document (the first 100 only).
void warn(Context& cx, const std::string& w) {
    if (cx.warnings.size() < 100) cx.warnings.push_back(w);
}

// The cascade for `node`, lowest priority first (later entries win): presentation attributes,
// then style sheet declarations by specificity and order, then the style attribute, then
// !important sheet declarations, then !important style attribute declarations.
const Properties& properties(Context& cx, const pugi::xml_node& node) {
    const auto cached = cx.property_cache.find(node.internal_object());
    if (cached != cx.property_cache.end()) return cached->second;
    Properties props;
    // `marker`, `mix-blend-mode` and `isolation` are CSS properties without a presentation
    // attribute (SVG 2): only style sheets and the style attribute set them.
    for (const pugi::xml_attribute& a : node.attributes()) {
        const std::string_view name = a.name();
        if (name != "marker" && name != "mix-blend-mode" && name != "isolation")
            props.emplace_back(a.name(), a.value());
    }
    std::vector<const css::Rule*> matched;
    for (const css::Rule& r : cx.sheet.rules)
        if (css::matches(r.selector, node)) matched.push_back(&r);
    std::stable_sort(matched.begin(), matched.end(), [](const css::Rule* a, const css::Rule* b) {
        return a->selector.specificity < b->selector.specificity;
    });
    const std::vector<css::Declaration> inline_decls = css::parse_declarations(node.attribute("style").value());
    for (bool important : {false, true}) {
        for (const css::Rule* r : matched)
            for (const css::Declaration& d : r->declarations)
                if (d.important == important) props.emplace_back(d.name, d.value);
        for (const css::Declaration& d : inline_decls)
            if (d.important == important) props.emplace_back(d.name, d.value);
    }
    return cx.property_cache.emplace(node.internal_object(), std::move(props)).first->second;
}

// Reads every <style> element (type empty or text/css) into the sheet.
void read_style_sheets(Context& cx, const pugi::xml_node& root) {
    for (pugi::xml_node n = root; n;) {
        if (std::string_view(n.name()) == "style") {
            const std::string_view type = trim(n.attribute("type").value());
            if (type.empty() || type == "text/css") {
                std::string text;
                for (const pugi::xml_node& c : n.children())
                    if (c.type() == pugi::node_pcdata || c.type() == pugi::node_cdata) text += c.value();
                css::parse_stylesheet(text, cx.sheet);
            }
        }
        if (pugi::xml_node c = n.first_child(); c && std::string_view(n.name()) != "style") {
            n = c;
            continue;
        }
        while (n && !n.next_sibling() && n != root) n = n.parent();
        if (!n || n == root) break;
        n = n.next_sibling();
    }
    if (cx.sheet.truncated)
        warn(cx, "style sheets hold more than " + std::to_string(current_limits().css_rules) +
                     " rules; the rest are ignored");
}

double font_size_of(Context& cx, const pugi::xml_node& node) {
    if (!node || node.type() != pugi::node_element) return kDefaultFontSize;
    const auto cached = cx.font_size_cache.find(node.internal_object());
    if (cached != cx.font_size_cache.end()) return cached->second;
    const double parent = font_size_of(cx, node.parent());
    double size = parent;
    for (const auto& [k, v] : properties(cx, node)) {
        const std::string_view val = trim(v);
        if (k == "font-size") {
            if (auto s = font_size(val, parent, cx.options.dpi)) size = *s;
        } else if (k == "font") {
            TextCtx t;
            t.font.size = size;
            apply_font_shorthand(cx, val, t, parent);
            size = t.font.size;
        }
    }
    return cx.font_size_cache.emplace(node.internal_object(), size).first->second;
}

void index_ids(Context& cx, const pugi::xml_node& root) {
    for (pugi::xml_node n = root; n;) {
        if (const char* id = n.attribute("id").value(); *id) cx.ids.emplace(id, n);
        if (pugi::xml_node c = n.first_child(); c) {
            n = c;
            continue;
        }
        while (n && !n.next_sibling() && n != root) n = n.parent();
        if (!n || n == root) break;
        n = n.next_sibling();
    }
}

pugi::xml_node lookup(const Context& cx, std::string_view id) {
    const auto it = cx.ids.find(std::string(id));
    return it == cx.ids.end() ? pugi::xml_node() : it->second;
}

std::string own_property(Context& cx, const pugi::xml_node& n, const std::string& name) {
    std::string out;
    for (const auto& [k, v] : properties(cx, n))
        if (k == name) out = std::string(trim(v));
    return out == "inherit" ? std::string() : out;
}

// The value of property `name` on `n` or its nearest ancestor that sets it (not `inherit`).
std::string inherited(Context& cx, pugi::xml_node n, const std::string& name) {
    for (; n && n.type() == pugi::node_element; n = n.parent())
        for (const auto& [k, v] : properties(cx, n))
            if (k == name && trim(v) != "inherit") return std::string(trim(v));
    return {};
}

// The overflow `n` sets itself ("inherit" included), empty when it sets none.
std::string own_overflow(Context& cx, const pugi::xml_node& n) {
    std::string out;
    for (const auto& [k, v] : properties(cx, n))
        if (k == "overflow") out = std::string(trim(v));
    return out;
}

// Sets property `name` of `n` to `value` over what the cascade gave it.
void override_property(Context& cx, const pugi::xml_node& n, const std::string& name, const std::string& value) {
    properties(cx, n);
    cx.property_cache[n.internal_object()].emplace_back(name, value);
}

bool is_active(const Context& cx, const pugi::xml_node& n) {
    return std::find(cx.active_refs.begin(), cx.active_refs.end(), n) != cx.active_refs.end();
}

// The element a clip-path or mask property (url(#id), not inherited) names; `missing` is set
// when it names nothing of kind `want`.
pugi::xml_node reference(Context& cx, const pugi::xml_node& n, const char* property, std::string_view want,
                         bool& missing) {
    std::string value;
    for (const auto& [k, v] : properties(cx, n))
        if (k == property) value = std::string(trim(v));
    if (value.empty() || value == "none" || value.substr(0, 4) != "url(") return {};
    const std::size_t close = value.find(')');
    std::string_view ref =
        trim(std::string_view(value).substr(4, close == std::string::npos ? std::string::npos : close - 4));
    if (ref.size() >= 2 && (ref.front() == '\'' || ref.front() == '"')) ref = ref.substr(1, ref.size() - 2);
    const pugi::xml_node target = !ref.empty() && ref.front() == '#' ? lookup(cx, ref.substr(1)) : pugi::xml_node();
    if (!target || std::string_view(target.name()) != want) {
        missing = true;
        return {};
    }
    return target;
}

}  // namespace casteljau::svg
