// Formats stage, SVG conversion: the glue between an element and its filters. Reads the `filter`
// property and gives filter_graphs.cpp, which builds the filter graphs, what only the conversion
// knows: the cascade, ids, lengths and the content of feImage.
#include "formats/svg/context.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "formats/svg/filter_graphs.hpp"

namespace casteljau::svg {

// The `filter` property of `n` as a list of steps, nullopt
// when it is absent, `none` or malformed (then it is ignored).
std::optional<std::vector<svg_filter::FilterRef>> filter_refs(Context& cx, const pugi::xml_node& n) {
    const std::string value = own_property(cx, n, "filter");
    if (value.empty() || value == "none") return std::nullopt;
    auto refs = svg_filter::parse_filter_property(value);
    if (!refs) warn(cx, std::string("<") + n.name() + ">: invalid filter '" + value + "' ignored");
    return refs;
}

svg_filter::SvgFilterEnv filter_env(Context& cx, const Style& st, Viewport vp, int depth) {
    svg_filter::SvgFilterEnv env;
    env.property = [&cx](const pugi::xml_node& n, const std::string& k) { return own_property(cx, n, k); };
    env.inherited = [&cx](const pugi::xml_node& n, const std::string& k) { return inherited(cx, n, k); };
    env.lookup = [&cx](std::string_view id) { return lookup(cx, id); };
    env.length = [fs = st.font_size, dpi = cx.options.dpi](std::string_view t, double pct) {
        return parse_length(t, pct, fs, dpi);
    };
    env.color = [](std::string_view t) { return parse_color(t); };
    env.viewport = vp;
    env.current_color = st.color;
    // feImage: the referenced element (drawn like a `use` in the filtered element's user
    // space) or the image, captured as items and drawn when the filter runs.
    env.image = [&cx, vp, depth](const pugi::xml_node& fe,
                                 const Rect& sub) -> std::function<void(Pixmap&, const Affine&)> {
        DisplayList captured;
        std::swap(captured, cx.items);
        const char* h = href(fe);
        if (*h == '#') {
            const pugi::xml_node target = lookup(cx, h + 1);
            if (std::find(cx.filtering.begin(), cx.filtering.end(), target) != cx.filtering.end())
                cx.filter_self_reference = true;
            else if (target && !is_active(cx, target)) {
                cx.active_refs.push_back(target);
                // Drawn like a `use`, placed at the subregion's origin (as resvg and Chrome do).
                element(cx, target, initial_style(cx.options), Affine::translate(sub.x0, sub.y0), vp, depth + 1);
                cx.active_refs.pop_back();
            }
        } else {
            pugi::xml_document placed;
            pugi::xml_node img = placed.append_copy(fe);
            // The image fills the primitive subregion (already in user units).
            auto set = [&](const char* name, double v) {
                img.remove_attribute(name);
                img.append_attribute(name) = v;
            };
            set("x", sub.x0);
            set("y", sub.y0);
            set("width", sub.width());
            set("height", sub.height());
            image(cx, img, Style(), Affine::identity(), vp, 1.0);
        }
        std::swap(captured, cx.items);
        if (captured.empty()) return {};
        auto shared = std::make_shared<const DisplayList>(std::move(captured));
        return [shared](Pixmap& pm, const Affine& m) {
            Canvas c(pm);
            draw(*shared, c, m);
        };
    };
    return env;
}

// The graphs of `refs` for element `n` with bounding box `bbox`; nullopt when one of them is
// invalid (the element is then not drawn).
std::optional<std::vector<filter::FilterGraph>> build_filters(Context& cx,
                                                              const std::vector<svg_filter::FilterRef>& refs,
                                                              const std::optional<Rect>& bbox, const Style& st,
                                                              Viewport vp, int depth) {
    const svg_filter::SvgFilterEnv env = filter_env(cx, st, vp, depth);
    std::vector<filter::FilterGraph> out;
    for (const svg_filter::FilterRef& r : refs) {
        std::optional<filter::FilterGraph> g;
        if (!r.url.empty()) {
            const pugi::xml_node f = lookup(cx, r.url);
            if (!f || std::string_view(f.name()) != "filter") return std::nullopt;
            cx.active_refs.push_back(f);
            g = svg_filter::build_filter(f, bbox, env);
            cx.active_refs.pop_back();
        } else {
            g = svg_filter::build_function(r, bbox, env);
        }
        if (!g) return std::nullopt;
        out.push_back(std::move(*g));
    }
    return out;
}

std::optional<ElementFilters> element_filters(Context& cx, const pugi::xml_node& child, const Style& cst, Viewport vp,
                                              int depth) {
    ElementFilters out;
    std::optional<std::vector<svg_filter::FilterRef>>& frefs = out.refs;
    frefs = filter_refs(cx, child);
    if (frefs) {
        // An invalid filter function makes the whole property invalid (ignored); a url naming
        // no filter hides the element when it stands alone and is skipped in a list (as resvg).
        const svg_filter::SvgFilterEnv env = filter_env(cx, cst, vp, depth);
        const bool bad_function = std::any_of(frefs->begin(), frefs->end(), [&](const svg_filter::FilterRef& r) {
            return r.url.empty() && !svg_filter::build_function(r, std::nullopt, env);
        });
        if (bad_function) {
            warn(cx, std::string("<") + child.name() + ">: invalid filter function; filter ignored");
            frefs.reset();
        }
    }
    if (frefs) {
        std::vector<svg_filter::FilterRef> kept;
        for (const svg_filter::FilterRef& r : *frefs) {
            if (!r.url.empty()) {
                const pugi::xml_node f = lookup(cx, r.url);
                if (!f || std::string_view(f.name()) != "filter") {
                    if (frefs->size() == 1) return std::nullopt;
                    continue;
                }
                out.nodes.push_back(f);
            }
            kept.push_back(r);
        }
        *frefs = std::move(kept);
    }
    if (std::any_of(out.nodes.begin(), out.nodes.end(), [&](const pugi::xml_node& f) { return is_active(cx, f); })) {
        // Drawn inside its own filter (through feImage): drawn without the filter.
        warn(cx, std::string("<") + child.name() + ">: recursive filter ignored");
        frefs.reset();
        out.nodes.clear();
    }
    return out;
}

bool finish_filters(Context& cx, const pugi::xml_node& child, const ElementFilters& filters, std::size_t filter_first,
                    const Affine& cm, const Style& cst, Viewport vp, int depth) {
    cx.filtering.push_back(child);
    const bool outer_self_reference = cx.filter_self_reference;
    cx.filter_self_reference = false;
    auto graphs = build_filters(cx, *filters.refs, items_bbox(cx, filter_first + 1, cm), cst, vp, depth);
    cx.filtering.pop_back();
    const bool self_reference = cx.filter_self_reference;
    cx.filter_self_reference = outer_self_reference;
    if (self_reference) {
        warn(cx, std::string("<") + child.name() + ">: feImage references the filtered element; filter ignored");
        cx.items.erase(cx.items.begin() + static_cast<std::ptrdiff_t>(filter_first));
        return true;
    }
    if (!graphs) return false;
    DisplayItem end = layer_item(DisplayItem::EndFilter, 1);
    end.transform = cm;
    end.filters = std::make_shared<const std::vector<filter::FilterGraph>>(std::move(*graphs));
    cx.items.push_back(std::move(end));
    return true;
}

}  // namespace casteljau::svg
