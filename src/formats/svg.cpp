// Formats stage: the SVG reader. Parses with pugixml into a display list of filled paths (user
// space Path + transform + paint + rule), with group-opacity layers, then renders that list onto a
// Canvas. See include/casteljau/svg.hpp for what is supported.
#include "casteljau/svg.hpp"

#include <pugixml.hpp>
#include <zlib.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <climits>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "casteljau/error.hpp"
#include "casteljau/limits.hpp"
#include "casteljau/filter.hpp"
#include "casteljau/image.hpp"
#include "casteljau/file_io.hpp"
#include "casteljau/shader.hpp"
#include "casteljau/stroke.hpp"
#include "casteljau/svg_path.hpp"
#include "casteljau/flatten.hpp"
#include "casteljau/text.hpp"
#include "formats/css.hpp"
#include "formats/svg_filter.hpp"
#include "formats/svg_text.hpp"
#include "formats/svg/display_list.hpp"
#include "formats/svg/values.hpp"
#include "formats/svg/xml_input.hpp"

namespace casteljau {

namespace {

using Item = svg::DisplayItem;
using svg::PatternTile;
using svg::gunzip;
using svg::normalise_namespaces;
using svg::parse_length;
using svg::parse_number;
using svg::parse_opacity;
using svg::parse_viewbox;
using svg::trim;
using svg::viewbox_transform;

// The element a context-fill or context-stroke paint comes from (the shape a marker is drawn on,
// or a use element): a paint server is resolved for its bounding box (the bounds of `path`) in its
// user space (`transform`: that space -> document pixels; vw x vh its viewport).
struct ContextElement {
    Path path;
    Affine transform;
    double vw = 100, vh = 100;
};

// A fill or stroke as specified: none, a colour, or a paint server (url(#id)) with its fallback.
struct PaintRef {
    enum Kind { None, Solid, Server } kind = None;
    Color color = Color::black();
    std::string id;        // Server: the referenced element's id
    Kind fallback = None;  // Server: what to paint when the reference is unusable
    Color fallback_color = Color::black();
    std::shared_ptr<const ContextElement> context;  // Server: set when the paint is context-fill/-stroke
    static PaintRef solid(Color c) {
        PaintRef p;
        p.kind = Solid;
        p.color = c;
        return p;
    }
};


// A path that counts in bounding boxes without being drawn.
Item bounds_item(Path path, const Affine& transform) {
    Item it;
    it.kind = Item::Bounds;
    it.path = std::move(path);
    it.transform = transform;
    return it;
}

Item layer_item(Item::Kind kind, double opacity) {
    Item it;
    it.kind = kind;
    it.opacity = opacity;
    return it;
}

// The font size where no element sets one: resvg's default, the size the text engine starts from.
constexpr double kDefaultFontSize = 12;

struct Style {
    PaintRef fill = PaintRef::solid(Color::black());
    Color color = Color::black();  // currentColor
    FillRule fill_rule = FillRule::NonZero;
    double fill_opacity = 1;
    PaintRef stroke;  // none (the SVG default)
    double stroke_opacity = 1;
    StrokeStyle stroke_style;
    bool visible = true;                               // visibility (inherited)
    std::array<int, 3> paint_order{0, 1, 2};           // paint-order: 0 fill, 1 stroke, 2 markers (inherited)
    std::string marker_start, marker_mid, marker_end;  // marker ids (inherited)
    // What context-fill and context-stroke name: the fill and stroke of the use element or of the
    // shape a marker is drawn on (none outside those).
    PaintRef context_fill, context_stroke;
    // The nearest viewport's size in user units: percentages of stroke-width, stroke-dasharray and
    // stroke-dashoffset are of its normalised diagonal sqrt((w^2 + h^2) / 2).
    double viewport_w = 100, viewport_h = 100;
    double font_size = kDefaultFontSize;  // the element's computed font-size (em in filter functions)
};


class Reader {
public:
    std::vector<Item> items;
    std::vector<std::string> warnings;
    const Limits limits_ = current_limits();  // read once per document

    void warn(const std::string& w) {
        if (warnings.size() < 100) warnings.push_back(w);
    }

    // Presentation attributes and the style attribute of `node`, later ones winning.
    using Properties = std::vector<std::pair<std::string, std::string>>;
    css::StyleSheet sheet;  // all <style> elements of the document, in order
    std::unordered_map<const void*, Properties> property_cache;

    // The cascade for `node`, lowest priority first (later entries win): presentation attributes,
    // then style sheet declarations by specificity and order, then the style attribute, then
    // !important sheet declarations, then !important style attribute declarations.
    const Properties& properties(const pugi::xml_node& node) {
        const auto cached = property_cache.find(node.internal_object());
        if (cached != property_cache.end()) return cached->second;
        Properties props;
        // `marker`, `mix-blend-mode` and `isolation` are CSS properties without a presentation
        // attribute (SVG 2): only style sheets and the style attribute set them.
        for (const pugi::xml_attribute& a : node.attributes()) {
            const std::string_view name = a.name();
            if (name != "marker" && name != "mix-blend-mode" && name != "isolation")
                props.emplace_back(a.name(), a.value());
        }
        std::vector<const css::Rule*> matched;
        for (const css::Rule& r : sheet.rules)
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
        return property_cache.emplace(node.internal_object(), std::move(props)).first->second;
    }

    // Reads every <style> element (type empty or text/css) into the sheet.
    void read_style_sheets(const pugi::xml_node& root) {
        for (pugi::xml_node n = root; n;) {
            if (std::string_view(n.name()) == "style") {
                const std::string_view type = trim(n.attribute("type").value());
                if (type.empty() || type == "text/css") {
                    std::string text;
                    for (const pugi::xml_node& c : n.children())
                        if (c.type() == pugi::node_pcdata || c.type() == pugi::node_cdata) text += c.value();
                    css::parse_stylesheet(text, sheet);
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
        if (sheet.truncated)
            warn("style sheets hold more than " + std::to_string(current_limits().css_rules) +
                 " rules; the rest are ignored");
    }

    // A fill or stroke value: none, currentColor, inherit (keeps the inherited paint), a colour,
    // or url(#id) with an optional fallback (none or a colour) after it.
    void apply_paint(const std::string& property, std::string_view value, Color current, PaintRef& paint) {
        auto simple = [&](std::string_view v, PaintRef::Kind& kind, Color& color) -> bool {
            if (v == "none") {
                kind = PaintRef::None;
                return true;
            }
            if (v == "currentColor") {
                kind = PaintRef::Solid;
                color = current;
                return true;
            }
            try {
                color = parse_color(v);
                kind = PaintRef::Solid;
                return true;
            } catch (const Error&) { return false; }
        };
        if (value == "inherit") return;
        if (value.substr(0, 4) == "url(") {
            const std::size_t close = value.find(')');
            if (close == std::string_view::npos) {
                warn("invalid " + property + " '" + std::string(value) + "'");
                return;
            }
            std::string_view ref = trim(value.substr(4, close - 4));
            if (ref.size() >= 2 && (ref.front() == '\'' || ref.front() == '"')) ref = ref.substr(1, ref.size() - 2);
            PaintRef p;
            p.kind = PaintRef::Server;
            p.id = ref.empty() || ref.front() != '#' ? std::string() : std::string(ref.substr(1));
            const std::string_view rest = trim(value.substr(close + 1));
            if (!rest.empty() && !simple(rest, p.fallback, p.fallback_color)) p.fallback = PaintRef::None;
            paint = p;
            return;
        }
        PaintRef p;
        if (simple(value, p.kind, p.color))
            paint = p;
        else
            warn("invalid " + property + " '" + std::string(value) + "'");
    }

    // The computed font-size of `node`: the font-size (or `font` shorthand) of its ancestors and
    // itself applied outermost first, from kDefaultFontSize (em and ex relative to the parent's).
    std::unordered_map<const void*, double> font_size_cache;
    double font_size_of(const pugi::xml_node& node) {
        if (!node || node.type() != pugi::node_element) return kDefaultFontSize;
        const auto cached = font_size_cache.find(node.internal_object());
        if (cached != font_size_cache.end()) return cached->second;
        const double parent = font_size_of(node.parent());
        double size = parent;
        for (const auto& [k, v] : properties(node)) {
            const std::string_view val = trim(v);
            if (k == "font-size") {
                if (auto s = font_size(val, parent)) size = *s;
            } else if (k == "font") {
                TextCtx t;
                t.font.size = size;
                apply_font_shorthand(val, t, parent);
                size = t.font.size;
            }
        }
        return font_size_cache.emplace(node.internal_object(), size).first->second;
    }

    void apply_style(const pugi::xml_node& node, Style& st) {
        const double font_size = font_size_of(node);
        st.font_size = font_size;
        const double diag = std::sqrt((st.viewport_w * st.viewport_w + st.viewport_h * st.viewport_h) / 2);
        // `color` first so that currentColor in the same element resolves to it.
        for (const auto& [k, v] : properties(node)) {
            if (k == "color") {
                try {
                    st.color = parse_color(trim(v));
                } catch (const Error&) { warn("invalid color '" + v + "'"); }
            }
        }
        for (const auto& [k, v] : properties(node)) {
            const std::string_view val = trim(v);
            if (k == "fill") {
                if (val == "context-fill")
                    st.fill = st.context_fill;
                else if (val == "context-stroke")
                    st.fill = st.context_stroke;
                else
                    apply_paint(k, val, st.color, st.fill);
            } else if (k == "fill-rule") {
                if (val == "evenodd")
                    st.fill_rule = FillRule::EvenOdd;
                else if (val == "nonzero")
                    st.fill_rule = FillRule::NonZero;
            } else if (k == "fill-opacity") {
                if (auto o = parse_opacity(val)) st.fill_opacity = *o;
            } else if (k == "stroke") {
                if (val == "context-fill")
                    st.stroke = st.context_fill;
                else if (val == "context-stroke")
                    st.stroke = st.context_stroke;
                else
                    apply_paint(k, val, st.color, st.stroke);
            } else if (k == "stroke-opacity") {
                if (auto o = parse_opacity(val)) st.stroke_opacity = *o;
            } else if (k == "stroke-width") {
                if (auto l = parse_length(val, diag, font_size)) {
                    if (*l >= 0) st.stroke_style.width = *l;
                }
            } else if (k == "stroke-linecap") {
                parse_line_cap(val, st.stroke_style.cap);
            } else if (k == "stroke-linejoin") {
                parse_line_join(val, st.stroke_style.join);
            } else if (k == "stroke-miterlimit") {
                if (auto n = parse_number(val); n && *n >= 1) st.stroke_style.miter_limit = *n;
            } else if (k == "stroke-dasharray") {
                st.stroke_style.dashes.clear();
                if (val != "none") {
                    std::string list(val);
                    for (char& c : list)
                        if (c == ',') c = ' ';
                    std::size_t pos = 0;
                    bool ok = true;
                    while (pos < list.size()) {
                        while (pos < list.size() && std::isspace(static_cast<unsigned char>(list[pos]))) ++pos;
                        if (pos >= list.size()) break;
                        std::size_t end = list.find(' ', pos);
                        if (end == std::string::npos) end = list.size();
                        auto l = parse_length(std::string_view(list).substr(pos, end - pos), diag, font_size);
                        if (!l || *l < 0) {
                            ok = false;
                            break;
                        }
                        st.stroke_style.dashes.push_back(*l);
                        pos = end;
                    }
                    if (!ok) st.stroke_style.dashes.clear();
                }
            } else if (k == "paint-order") {
                // The keywords given, in their order, then the missing ones in the normal order.
                std::array<int, 3> order{};
                std::size_t n = 0;
                bool ok = true;
                for (std::string_view rest = val; !rest.empty() && val != "normal";) {
                    const std::size_t sp = rest.find(' ');
                    const std::string_view w = rest.substr(0, sp);
                    rest = sp == std::string_view::npos ? std::string_view{} : trim(rest.substr(sp));
                    const int id = w == "fill" ? 0 : w == "stroke" ? 1 : w == "markers" ? 2 : -1;
                    if (id < 0 || std::find(order.begin(), order.begin() + n, id) != order.begin() + n) {
                        ok = false;
                        break;
                    }
                    order[n++] = id;
                }
                if (ok) {
                    for (int id = 0; id < 3; ++id)
                        if (std::find(order.begin(), order.begin() + n, id) == order.begin() + n) order[n++] = id;
                    st.paint_order = order;
                }
            } else if (k == "marker-start" || k == "marker-mid" || k == "marker-end" || k == "marker") {
                std::string id;
                if (val.substr(0, 5) == "url(#") {
                    const std::size_t close = val.find(')');
                    if (close != std::string_view::npos) id = std::string(trim(val.substr(5, close - 5)));
                } else if (val != "none") {
                    continue;
                }
                if (k == "marker-start" || k == "marker") st.marker_start = id;
                if (k == "marker-mid" || k == "marker") st.marker_mid = id;
                if (k == "marker-end" || k == "marker") st.marker_end = id;
            } else if (k == "visibility") {
                if (val == "visible")
                    st.visible = true;
                else if (val == "hidden" || val == "collapse")
                    st.visible = false;
            } else if (k == "stroke-dashoffset") {
                if (auto l = parse_length(val, diag, font_size)) st.stroke_style.dash_offset = *l;
            }
        }
    }

    double length_attr(const pugi::xml_node& n, const char* name, double percent_of, double fallback = 0) {
        const char* v = n.attribute(name).value();
        if (!*v) return fallback;
        auto l = parse_length(v, percent_of, font_size_of(n));
        if (!l) {
            warn(std::string("invalid ") + name + " '" + v + "' on <" + n.name() + ">");
            return fallback;
        }
        return *l;
    }

    std::optional<Path> shape_path(const pugi::xml_node& n, double vw, double vh) {
        const std::string_view name = n.name();
        const double diag = std::sqrt((vw * vw + vh * vh) / 2);
        Path p;
        if (name == "path") {
            std::string err;
            p = parse_svg_path_lenient(n.attribute("d").value(), &err);
            if (!err.empty()) warn(err);
        } else if (name == "rect") {
            const double x = length_attr(n, "x", vw), y = length_attr(n, "y", vh);
            const double w = length_attr(n, "width", vw), h = length_attr(n, "height", vh);
            if (!(w > 0) || !(h > 0)) return std::nullopt;
            double rx = length_attr(n, "rx", vw, -1), ry = length_attr(n, "ry", vh, -1);
            if (rx < 0 && ry < 0)
                rx = ry = 0;
            else if (rx < 0)
                rx = ry;
            else if (ry < 0)
                ry = rx;
            p.add_round_rect(Rect::from_xywh(x, y, w, h), std::min(rx, w / 2), std::min(ry, h / 2));
        } else if (name == "circle") {
            const double r = length_attr(n, "r", diag);
            if (!(r > 0)) return std::nullopt;
            p.add_circle({length_attr(n, "cx", vw), length_attr(n, "cy", vh)}, r);
        } else if (name == "ellipse") {
            double rx = length_attr(n, "rx", vw, -1), ry = length_attr(n, "ry", vh, -1);
            if (rx < 0 && ry < 0) return std::nullopt;
            if (rx < 0) rx = ry;
            if (ry < 0) ry = rx;
            if (!(rx > 0) || !(ry > 0)) return std::nullopt;
            p.add_ellipse({length_attr(n, "cx", vw), length_attr(n, "cy", vh)}, rx, ry);
        } else if (name == "line") {
            p.move_to(length_attr(n, "x1", vw), length_attr(n, "y1", vh));
            p.line_to(length_attr(n, "x2", vw), length_attr(n, "y2", vh));
        } else if (name == "polyline" || name == "polygon") {
            std::string err;
            p = parse_points_lenient(n.attribute("points").value(), name == "polygon", &err);
            if (!err.empty()) warn("<" + std::string(name) + ">: " + err);
            if (p.points().size() < 2) return std::nullopt;
        } else {
            return std::nullopt;
        }
        return p;
    }

    // Element ids of the whole document (the first element with an id wins).
    std::unordered_map<std::string, pugi::xml_node> ids;

    void index_ids(const pugi::xml_node& root) {
        for (pugi::xml_node n = root; n;) {
            if (const char* id = n.attribute("id").value(); *id) ids.emplace(id, n);
            if (pugi::xml_node c = n.first_child(); c) {
                n = c;
                continue;
            }
            while (n && !n.next_sibling() && n != root) n = n.parent();
            if (!n || n == root) break;
            n = n.next_sibling();
        }
    }

    pugi::xml_node lookup(std::string_view id) const {
        const auto it = ids.find(std::string(id));
        return it == ids.end() ? pugi::xml_node() : it->second;
    }

    // `href` takes precedence over `xlink:href` (SVG 2).
    static const char* href(const pugi::xml_node& n) {
        if (const char* h = n.attribute("href").value(); *h) return h;
        return n.attribute("xlink:href").value();
    }

    std::string own_property(const pugi::xml_node& n, const std::string& name) {
        std::string out;
        for (const auto& [k, v] : properties(n))
            if (k == name) out = std::string(trim(v));
        return out == "inherit" ? std::string() : out;
    }

    // The value of property `name` on `n` or its nearest ancestor that sets it (not `inherit`).
    std::string inherited(pugi::xml_node n, const std::string& name) {
        for (; n && n.type() == pugi::node_element; n = n.parent())
            for (const auto& [k, v] : properties(n))
                if (k == name && trim(v) != "inherit") return std::string(trim(v));
        return {};
    }

    // Sets the colour or shader of `it` for `ref` drawn on `path` (user space, for
    // objectBoundingBox units); false when nothing is to be painted.
    // resolve_paint for an element drawn with `cm` (its user space -> document pixels): a context
    // paint server is resolved for the context element, in its user space, then mapped into ours.
    bool resolve_paint(const PaintRef& ref, const Path& path, const Affine& cm, double vw, double vh, Item& it) {
        if (ref.kind != PaintRef::Server || !ref.context) return resolve_paint(ref, path, vw, vh, it);
        const ContextElement& ctx = *ref.context;
        if (!resolve_paint(ref, ctx.path, ctx.vw, ctx.vh, it)) return false;
        const auto inv = cm.inverse();
        if (!inv) return false;
        const Affine rel = *inv * ctx.transform;  // context user space -> this element's user space
        if (it.shader) it.shader = std::make_shared<const Shader>(it.shader->transformed(rel));
        if (it.pattern) {
            auto tile = std::make_shared<PatternTile>(*it.pattern);
            tile->transform = rel * tile->transform;
            it.pattern = std::move(tile);
        }
        return true;
    }

    bool resolve_paint(const PaintRef& ref, const Path& path, double vw, double vh, Item& it) {
        if (ref.kind == PaintRef::None) return false;
        if (ref.kind == PaintRef::Solid) {
            it.color = ref.color;
            return true;
        }
        const pugi::xml_node server = lookup(ref.id);
        const std::string_view kind = server ? server.name() : "";
        if (kind == "linearGradient" || kind == "radialGradient") {
            if (gradient(server, path, vw, vh, it)) return true;
            // An unusable gradient (no stops) takes the fallback colour when there is one.
            if (ref.fallback != PaintRef::Solid) return false;
            it.shader.reset();
            it.color = ref.fallback_color;
            return true;
        }
        if (!server || ref.fallback != PaintRef::None) {
            if (ref.fallback == PaintRef::Solid) {
                it.color = ref.fallback_color;
                return true;
            }
            if (!server) warn("paint server '#" + ref.id + "' not found; painted as none");
            return false;
        }
        if (kind == "pattern") {
            if (pattern(server, path, vw, vh, it)) return true;
            if (ref.fallback != PaintRef::Solid) return false;
            it.color = ref.fallback_color;
            return true;
        }
        warn("<" + std::string(kind) + "> is not a paint server; painted as none");
        return false;
    }

    // A linearGradient or radialGradient with its href chain: attributes come from the first
    // element of the chain that has them, stops from the first that has any.
    bool gradient(const pugi::xml_node& node, const Path& path, double vw, double vh, Item& it) {
        std::vector<pugi::xml_node> chain{node};
        while (chain.size() < 32) {
            const char* h = href(chain.back());
            if (*h != '#') break;
            const pugi::xml_node next = lookup(h + 1);
            const std::string_view nk = next ? next.name() : "";
            if (nk != "linearGradient" && nk != "radialGradient") break;
            if (std::find(chain.begin(), chain.end(), next) != chain.end()) break;  // a cycle ends the chain
            chain.push_back(next);
        }
        const std::string_view kind = node.name();
        auto attr = [&](const char* name, bool same_kind_only) -> std::string_view {
            for (const pugi::xml_node& n : chain) {
                if (same_kind_only && std::string_view(n.name()) != kind) continue;
                if (const char* v = n.attribute(name).value(); *v) return v;
            }
            return {};
        };
        // Stops.
        std::vector<GradientStop> stops;
        for (const pugi::xml_node& n : chain) {
            for (const pugi::xml_node& s : n.children("stop")) {
                GradientStop st;
                std::string_view off = trim(s.attribute("offset").value());
                double o = 0;
                if (!off.empty() && off.back() == '%') {
                    if (auto v = parse_number(off.substr(0, off.size() - 1))) o = *v / 100;
                } else if (auto v = parse_number(off)) {
                    o = *v;
                }
                st.offset = std::clamp(o, 0.0, 1.0);
                if (!stops.empty()) st.offset = std::max(st.offset, stops.back().offset);
                Color color = Color::black();
                double opacity = 1;
                for (const auto& [k, v] : properties(s)) {
                    std::string val(trim(v));
                    // stop-color and stop-opacity are not inherited: `inherit` takes the parent's
                    // own value, or the initial one.
                    if (val == "inherit")
                        val = k == "stop-color" || k == "stop-opacity" ? own_property(s.parent(), k) : "";
                    if (k == "stop-color" && !val.empty()) {
                        if (val == "currentColor") val = inherited(s, "color");
                        try {
                            color = parse_color(val.empty() ? "black" : val);
                        } catch (const Error&) { warn("invalid stop-color '" + v + "'"); }
                    } else if (k == "stop-opacity") {
                        if (auto op = parse_opacity(val)) opacity = *op;
                    }
                }
                st.color = color.with_opacity(opacity);
                stops.push_back(st);
            }
            if (!stops.empty()) break;
        }
        if (stops.empty()) return false;  // no stops: painted as none
        if (stops.size() == 1) {
            it.color = stops.front().color;
            return true;
        }
        const bool bbox_units = attr("gradientUnits", false) != "userSpaceOnUse";
        Affine gt;
        if (const std::string_view t = attr("gradientTransform", false); !t.empty()) {
            try {
                gt = parse_svg_transform(t);
                if (!gt.inverse()) gt = Affine{};  // a singular gradientTransform is ignored
                gt = bbox_units ? with_origin(node, gt, 1, 1) : with_origin(node, gt, vw, vh);
            } catch (const Error&) { warn("invalid gradientTransform; ignored"); }
        }
        SpreadMethod spread = SpreadMethod::Pad;
        if (const std::string_view sm = attr("spreadMethod", false); sm == "reflect")
            spread = SpreadMethod::Reflect;
        else if (sm == "repeat")
            spread = SpreadMethod::Repeat;
        const double diag = std::sqrt((vw * vw + vh * vh) / 2);
        auto coord = [&](const char* name, double percent_of, double fallback) {
            const std::string_view v = attr(name, true);
            if (v.empty()) return fallback;
            auto l = parse_length(v, bbox_units ? 1.0 : percent_of);
            return l ? *l : fallback;
        };
        Affine units;
        if (bbox_units) {
            const Rect b = path.bounds();
            if (!(b.width() > 0) || !(b.height() > 0)) return false;  // objectBoundingBox of a zero-size box
            units = Affine::translate(b.x0, b.y0) * Affine::scale(b.width(), b.height());
        }
        if (kind == "linearGradient") {
            const Point p0{coord("x1", vw, 0), coord("y1", vh, 0)};
            const Point p1{coord("x2", vw, bbox_units ? 1.0 : vw), coord("y2", vh, 0)};
            it.shader = std::make_shared<const Shader>(Shader::linear(p0, p1, std::move(stops), spread, units * gt));
            return true;
        }
        const double half_w = bbox_units ? 0.5 : vw / 2, half_h = bbox_units ? 0.5 : vh / 2;
        const double cx = coord("cx", vw, half_w), cy = coord("cy", vh, half_h);
        // A negative radius is invalid and falls back to the default.
        double r = coord("r", diag, bbox_units ? 0.5 : diag / 2);
        if (r < 0) r = bbox_units ? 0.5 : diag / 2;
        const double fx = coord("fx", vw, cx), fy = coord("fy", vh, cy);
        const double fr = std::max(0.0, coord("fr", diag, 0));
        it.shader = std::make_shared<const Shader>(
            Shader::radial({cx, cy}, r, {fx, fy}, fr, std::move(stops), spread, units * gt));
        return true;
    }

    // Elements drawn or expanded so far (each `use` copy counts again): the bound on use bombs.
    std::size_t expanded = 0;
    // The `use` elements being expanded (innermost last): a use whose target contains one of
    // them, or is one of them, is a cycle.
    std::vector<pugi::xml_node> use_stack;

    // Filters (src/formats/svg_filter.cpp builds the graphs; these methods give it the cascade,
    // ids, lengths and feImage content). The `filter` property of `n` as a list of steps, nullopt
    // when it is absent, `none` or malformed (then it is ignored).
    std::optional<std::vector<svg_filter::FilterRef>> filter_refs(const pugi::xml_node& n) {
        const std::string value = own_property(n, "filter");
        if (value.empty() || value == "none") return std::nullopt;
        auto refs = svg_filter::parse_filter_property(value);
        if (!refs) warn(std::string("<") + n.name() + ">: invalid filter '" + value + "' ignored");
        return refs;
    }

    // The elements whose filters are being built, and whether an feImage named one of them (the
    // filter is then ignored and the element drawn unfiltered, as resvg does).
    std::vector<pugi::xml_node> filtering;
    bool filter_self_reference = false;

    svg_filter::SvgFilterEnv filter_env(const Style& st, double vw, double vh, int depth) {
        svg_filter::SvgFilterEnv env;
        env.property = [this](const pugi::xml_node& n, const std::string& k) { return own_property(n, k); };
        env.inherited = [this](const pugi::xml_node& n, const std::string& k) { return inherited(n, k); };
        env.lookup = [this](std::string_view id) { return lookup(id); };
        env.length = [fs = st.font_size](std::string_view t, double pct) { return parse_length(t, pct, fs); };
        env.color = [](std::string_view t) { return parse_color(t); };
        env.vw = vw;
        env.vh = vh;
        env.current_color = st.color;
        // feImage: the referenced element (drawn like a `use` in the filtered element's user
        // space) or the image, captured as items and drawn when the filter runs.
        env.image = [this, vw, vh, depth](const pugi::xml_node& fe,
                                          const Rect& sub) -> std::function<void(Pixmap&, const Affine&)> {
            std::vector<Item> captured;
            std::swap(captured, items);
            const char* h = href(fe);
            if (*h == '#') {
                const pugi::xml_node target = lookup(h + 1);
                if (std::find(filtering.begin(), filtering.end(), target) != filtering.end())
                    filter_self_reference = true;
                else if (target && !is_active(target)) {
                    active_refs.push_back(target);
                    // Drawn like a `use`, placed at the subregion's origin (as resvg and Chrome do).
                    element(target, Style(), Affine::translate(sub.x0, sub.y0), vw, vh, depth + 1);
                    active_refs.pop_back();
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
                image(img, Style(), Affine::identity(), vw, vh, 1.0);
            }
            std::swap(captured, items);
            if (captured.empty()) return {};
            auto shared = std::make_shared<const std::vector<Item>>(std::move(captured));
            return [shared](Pixmap& pm, const Affine& m) {
                Canvas c(pm);
                svg::draw(*shared, c, m);
            };
        };
        return env;
    }

    // The graphs of `refs` for element `n` with bounding box `bbox`; nullopt when one of them is
    // invalid (the element is then not drawn).
    std::optional<std::vector<filter::FilterGraph>> build_filters(const std::vector<svg_filter::FilterRef>& refs,
                                                                  const std::optional<Rect>& bbox, const Style& st,
                                                                  double vw, double vh, int depth) {
        const svg_filter::SvgFilterEnv env = filter_env(st, vw, vh, depth);
        std::vector<filter::FilterGraph> out;
        for (const svg_filter::FilterRef& r : refs) {
            std::optional<filter::FilterGraph> g;
            if (!r.url.empty()) {
                const pugi::xml_node f = lookup(r.url);
                if (!f || std::string_view(f.name()) != "filter") return std::nullopt;
                active_refs.push_back(f);
                g = svg_filter::build_filter(f, bbox, env);
                active_refs.pop_back();
            } else {
                g = svg_filter::build_function(r, bbox, env);
            }
            if (!g) return std::nullopt;
            out.push_back(std::move(*g));
        }
        return out;
    }

    void walk(const pugi::xml_node& node, const Style& st, const Affine& m, double vw, double vh, int depth) {
        if (depth > limits_.nesting_depth)
            throw Error(ErrorKind::Limit, "SVG elements nested deeper than " + std::to_string(limits_.nesting_depth));
        const bool is_switch = std::string_view(node.name()) == "switch";
        for (const pugi::xml_node& child : node.children()) {
            if (child.type() != pugi::node_element) continue;
            if (!conditions_pass(child)) continue;
            element(child, st, m, vw, vh, depth);
            if (is_switch && known_element(child.name())) break;  // a switch draws its first passing child only
        }
    }

    static bool known_element(std::string_view n) {
        return n == "g" || n == "a" || n == "switch" || n == "svg" || n == "use" || n == "path" || n == "rect" ||
               n == "circle" || n == "ellipse" || n == "line" || n == "polyline" || n == "polygon" || n == "image" ||
               n == "text" || n == "foreignObject";
    }

    // Conditional processing: systemLanguage (the user language is English), requiredExtensions
    // (none supported); requiredFeatures is always true (SVG 2).
    static bool conditions_pass(const pugi::xml_node& n) {
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

    // A clip to `r` (user space of `m`) around the items that `draw` adds.
    template <class F>
    void clipped(const Rect& r, const Affine& m, F&& draw) {
        Item push;
        push.kind = Item::PushClip;
        push.path.add_rect(r);
        push.transform = m;
        items.push_back(std::move(push));
        draw();
        Item pop;
        pop.kind = Item::PopClip;
        items.push_back(std::move(pop));
    }

    // transform-origin ("x [y]": lengths, percentages of the viewport, or the keywords left,
    // center, right, top, bottom in either order) wrapped around a transform `t`:
    // translate(origin) * t * translate(-origin).
    Affine with_origin(const pugi::xml_node& n, const Affine& t, double vw, double vh) {
        std::string value;
        for (const auto& [k, v] : properties(n))
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
        if (words.size() == 2 &&
            (words[0] == "top" || words[0] == "bottom" || words[1] == "left" || words[1] == "right"))
            std::swap(words[0], words[1]);
        auto axis = [&](const std::string& word, double size, bool horizontal) -> double {
            if (word == "center") return size / 2;
            if (horizontal ? word == "left" : word == "top") return 0;
            if (horizontal ? word == "right" : word == "bottom") return size;
            auto l = parse_length(word, size);
            return l ? *l : size / 2;
        };
        double ox, oy;
        if (words.size() == 1) {
            if (words[0] == "top" || words[0] == "bottom") {
                ox = vw / 2;
                oy = axis(words[0], vh, false);
            } else {
                ox = axis(words[0], vw, true);
                oy = vh / 2;
            }
        } else {
            ox = axis(words[0], vw, true);
            oy = axis(words[1], vh, false);
        }
        return Affine::translate(ox, oy) * t * Affine::translate(-ox, -oy);
    }

    // A new viewport (nested svg, or a symbol or svg instanced by use) at x, y, w x h in the
    // user space of `m`, with its viewBox and preserveAspectRatio; clipped unless overflow is
    // visible or auto.
    void viewport(const pugi::xml_node& n, const Style& st, const Affine& m, double x, double y, double w, double h,
                  int depth, bool is_symbol) {
        if (!(w > 0) || !(h > 0)) return;
        Affine inner = m * Affine::translate(x, y);
        double nvw = w, nvh = h;
        if (auto vb = parse_viewbox(n.attribute("viewBox").value())) {
            inner = inner * viewbox_transform(*vb, n.attribute("preserveAspectRatio").value(), w, h);
            nvw = vb->width();
            nvh = vb->height();
        }
        if (is_symbol) {
            const double rx = length_attr(n, "refX", nvw), ry = length_attr(n, "refY", nvh);
            inner = inner * Affine::translate(-rx, -ry);
        }
        std::string overflow;
        for (const auto& [k, v] : properties(n))
            if (k == "overflow") overflow = std::string(trim(v));
        auto draw = [&] { walk(n, st, inner, nvw, nvh, depth + 1); };
        if (overflow == "visible" || overflow == "auto")
            draw();
        else
            clipped(Rect::from_xywh(x, y, w, h), m, draw);
    }

    bool measuring_use = false;  // inside the first pass that measures a use element's box

    void use(const pugi::xml_node& u, const Style& st, const Affine& m, double vw, double vh, int depth) {
        const char* h = href(u);
        const pugi::xml_node target = *h == '#' ? lookup(h + 1) : pugi::xml_node();
        if (!target) {
            if (*h) warn(std::string("<use> target '") + h + "' not found; skipped");
            return;
        }
        // A cycle: the target is the use itself or one of its ancestors, or contains a use being
        // expanded.
        for (pugi::xml_node a = u; a; a = a.parent())
            if (a == target) {
                warn(std::string("<use> '") + h + "' references itself; skipped");
                return;
            }
        for (const pugi::xml_node& active : use_stack)
            for (pugi::xml_node a = active; a; a = a.parent())
                if (a == target) {
                    warn(std::string("<use> '") + h + "' is part of a reference cycle; skipped");
                    return;
                }
        const double x = length_attr(u, "x", vw), y = length_attr(u, "y", vh);
        use_stack.push_back(u);
        Style ust = st;
        ust.context_fill = st.fill;
        ust.context_stroke = st.stroke;
        if (measuring_use) {
            // Only geometry counts while measuring: context paint servers become solid.
            if (ust.context_fill.kind == PaintRef::Server) ust.context_fill = PaintRef::solid(Color::black());
            if (ust.context_stroke.kind == PaintRef::Server) ust.context_stroke = PaintRef::solid(Color::black());
        }
        const std::string_view tn = target.name();
        const bool instance = tn == "symbol" || tn == "svg";
        if (!measuring_use && ((st.fill.kind == PaintRef::Server && !st.fill.context) ||
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
            context->vw = vw;
            context->vh = vh;
            const std::size_t first = items.size(), warned = warnings.size(), text_before = text_chars_total;
            Style probe = st;
            probe.fill = probe.stroke = PaintRef::solid(Color::black());
            use_stack.pop_back();
            measuring_use = true;
            try {
                use(u, probe, m, vw, vh, depth);
            } catch (...) {
                measuring_use = false;
                throw;
            }
            measuring_use = false;
            use_stack.push_back(u);
            if (const std::optional<Rect> box = items_bbox(first, context->transform)) context->path.add_rect(*box);
            items.resize(first);
            warnings.resize(warned);
            text_chars_total = text_before;
            ust.context_fill = context_paint(st.fill, context);
            ust.context_stroke = context_paint(st.stroke, context);
        }
        if (instance) {
            const pugi::xml_node size_from = u.attribute("width") ? u : target;
            const pugi::xml_node hsize_from = u.attribute("height") ? u : target;
            const double w = length_attr(size_from, "width", vw, vw), hh = length_attr(hsize_from, "height", vh, vh);
            const double tx = tn == "svg" ? length_attr(target, "x", vw) : 0,
                         ty = tn == "svg" ? length_attr(target, "y", vh) : 0;
            Style tst = ust;
            apply_style(target, tst);
            // The instanced symbol or svg keeps its own opacity.
            double op = 1;
            for (const auto& [k, v] : properties(target))
                if (k == "opacity")
                    if (auto o = parse_opacity(v)) op = *o;
            if (op < 1) items.push_back(layer_item(Item::BeginLayer, op));
            viewport(target, tst, m, x + tx, y + ty, w, hh, depth + 1, tn == "symbol");
            if (op < 1) items.push_back(layer_item(Item::EndLayer, op));
        } else {
            element(target, ust, m * Affine::translate(x, y), vw, vh, depth + 1);
        }
        use_stack.pop_back();
    }

    // clip-path and mask references being expanded: a reference back to one of them is a cycle.
    std::vector<pugi::xml_node> active_refs;

    bool is_active(const pugi::xml_node& n) const {
        return std::find(active_refs.begin(), active_refs.end(), n) != active_refs.end();
    }

    // The element a clip-path or mask property (url(#id), not inherited) names; `missing` is set
    // when it names nothing of kind `want`.
    pugi::xml_node reference(const pugi::xml_node& n, const char* property, std::string_view want, bool& missing) {
        std::string value;
        for (const auto& [k, v] : properties(n))
            if (k == property) value = std::string(trim(v));
        if (value.empty() || value == "none" || value.substr(0, 4) != "url(") return {};
        const std::size_t close = value.find(')');
        std::string_view ref =
            trim(std::string_view(value).substr(4, close == std::string::npos ? std::string::npos : close - 4));
        if (ref.size() >= 2 && (ref.front() == '\'' || ref.front() == '"')) ref = ref.substr(1, ref.size() - 2);
        const pugi::xml_node target = !ref.empty() && ref.front() == '#' ? lookup(ref.substr(1)) : pugi::xml_node();
        if (!target || std::string_view(target.name()) != want) {
            missing = true;
            return {};
        }
        return target;
    }

    // Bounding box, in the user space of `m`, of the fills and strokes among items[first..]
    // (leaving out the content of clips and masks); the path geometry, not the stroke outline.
    std::optional<Rect> items_bbox(std::size_t first, const Affine& m) const {
        const auto inv = m.inverse();
        if (!inv) return std::nullopt;
        std::optional<Rect> box;
        int hidden = 0;
        for (std::size_t i = first; i < items.size(); ++i) {
            const Item& it = items[i];
            if (it.kind == Item::BeginClip || it.kind == Item::BeginMask)
                ++hidden;
            else if (it.kind == Item::EndMask)
                --hidden;
            else if (hidden == 0 && (it.kind == Item::Fill || it.kind == Item::Stroke || it.kind == Item::Bounds)) {
                const Rect b = transform_bounds(*inv * it.transform, it.path.bounds());
                box = box ? box->united(b) : b;
            }
        }
        return box;
    }

    // A clipPath's children drawn as opaque coverage into a mask layer that multiplies the
    // enclosing layer. clipPathUnits objectBoundingBox maps 0..1 onto `box`.
    void emit_clip(const pugi::xml_node& clip, const Affine& cm, const std::optional<Rect>& box, double vw, double vh,
                   int depth) {
        active_refs.push_back(clip);
        Item begin;
        begin.kind = Item::BeginClip;
        items.push_back(std::move(begin));
        Affine m = cm;
        bool ok = true;
        if (const char* t = clip.attribute("transform").value(); *t) {
            try {
                m = m * with_origin(clip, parse_svg_transform(t), vw, vh);
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
        pugi::xml_node inner = reference(clip, "clip-path", "clipPath", inner_missing);
        if (inner && is_active(inner)) inner = {};  // a reference back into the cycle is ignored (as resvg does)
        if (ok) {
            if (inner) items.push_back(layer_item(Item::BeginLayer, 1));
            FillRule rule = FillRule::NonZero;
            for (const auto& [k, v] : properties(clip))
                if (k == "clip-rule") rule = trim(v) == "evenodd" ? FillRule::EvenOdd : FillRule::NonZero;
            for (const pugi::xml_node& c : clip.children())
                if (c.type() == pugi::node_element) clip_child(c, c, m, rule, vw, vh, depth + 1);
            if (inner) {
                emit_clip(inner, cm, box, vw, vh, depth + 1);
                items.push_back(layer_item(Item::EndLayer, 1));
            }
        }
        Item end;
        end.kind = Item::EndMask;
        items.push_back(std::move(end));
        active_refs.pop_back();
    }

    // One child of a clipPath: a shape (or a use of a shape), its own transform, clip-rule and
    // clip-path; fill, stroke and opacity have no effect.
    void clip_child(const pugi::xml_node& c, const pugi::xml_node& props, const Affine& m, FillRule rule, double vw,
                    double vh, int depth) {
        if (depth > limits_.nesting_depth)
            throw Error(ErrorKind::Limit, "SVG elements nested deeper than " + std::to_string(limits_.nesting_depth));
        if (++expanded > limits_.svg_elements)
            throw Error(ErrorKind::Limit,
                        "SVG expands to more than " + std::to_string(limits_.svg_elements) + " elements");
        if (!conditions_pass(c)) return;
        bool visible = true;
        for (const auto& [k, v] : properties(c)) {
            const std::string_view val = trim(v);
            if (k == "display" && val == "none") return;
            if (k == "visibility") visible = val == "visible";
            if (k == "clip-rule") rule = val == "evenodd" ? FillRule::EvenOdd : FillRule::NonZero;
        }
        if (!visible) return;
        Affine cm = m;
        if (const char* t = c.attribute("transform").value(); *t) {
            try {
                cm = m * with_origin(c, parse_svg_transform(t), vw, vh);
            } catch (const Error&) { return; }
        }
        const std::string_view name = c.name();
        if (name == "use") {
            const char* h = href(c);
            const pugi::xml_node target = *h == '#' ? lookup(h + 1) : pugi::xml_node();
            if (!target || is_active(target)) return;
            const std::string_view tn = target.name();
            if (tn != "path" && tn != "rect" && tn != "circle" && tn != "ellipse" && tn != "polyline" &&
                tn != "polygon" && tn != "text")
                return;  // only shapes may be used inside a clipPath
            active_refs.push_back(target);
            clip_child(target, c, cm * Affine::translate(length_attr(c, "x", vw), length_attr(c, "y", vh)), rule, vw,
                       vh, depth + 1);
            active_refs.pop_back();
            return;
        }
        (void)props;
        if (name == "text") {
            std::vector<Style> styles;
            for (svg_text::Outline& o : text_outlines(c, Style{}, vw, vh, styles)) {
                if (o.layer == svg_text::Outline::Glyphs && o.path.empty()) continue;
                Item it;
                it.kind = Item::Fill;
                it.color = Color::black();
                it.rule = rule;
                it.transform = cm;
                it.path = std::move(o.path);
                items.push_back(std::move(it));
            }
            return;
        }
        std::optional<Path> p = shape_path(c, vw, vh);
        if (!p || p->empty() || name == "line") return;
        bool missing = false;
        pugi::xml_node own = reference(c, "clip-path", "clipPath", missing);
        if (own && is_active(own)) own = {};  // a reference back into the cycle is ignored (as resvg does)
        if (own) items.push_back(layer_item(Item::BeginLayer, 1));
        Item it;
        it.kind = Item::Fill;
        it.color = Color::black();
        it.rule = rule;
        it.transform = cm;
        const Rect b = p->bounds();
        it.path = std::move(*p);
        items.push_back(std::move(it));
        if (own) {
            emit_clip(own, cm, b, vw, vh, depth + 1);
            items.push_back(layer_item(Item::EndLayer, 1));
        }
    }

    // A mask's content drawn into a mask layer (luminance, or alpha with mask-type="alpha"),
    // clipped to the mask region, that multiplies the enclosing layer.
    void emit_mask(const pugi::xml_node& mask, const Affine& cm, const std::optional<Rect>& box, double vw, double vh,
                   int depth) {
        active_refs.push_back(mask);
        Item begin;
        begin.kind = Item::BeginMask;
        std::string type;
        for (const auto& [k, v] : properties(mask))
            if (k == "mask-type") type = std::string(trim(v));
        begin.luminance = type != "alpha";
        items.push_back(std::move(begin));
        const bool bbox_units = std::string_view(mask.attribute("maskUnits").value()) != "userSpaceOnUse";
        const bool content_bbox = std::string_view(mask.attribute("maskContentUnits").value()) == "objectBoundingBox";
        const bool have_box = box && box->width() > 0 && box->height() > 0;
        if (have_box || (!bbox_units && !content_bbox)) {
            Rect region;
            auto frac = [&](const char* name, double fallback) {
                const char* v = mask.attribute(name).value();
                if (!*v) return fallback;
                auto l = parse_length(v, 1.0);
                return l ? *l : fallback;
            };
            if (bbox_units) {
                region =
                    Rect::from_xywh(box->x0 + frac("x", -0.1) * box->width(), box->y0 + frac("y", -0.1) * box->height(),
                                    frac("width", 1.2) * box->width(), frac("height", 1.2) * box->height());
            } else {
                region = Rect::from_xywh(length_attr(mask, "x", vw, -0.1 * vw), length_attr(mask, "y", vh, -0.1 * vh),
                                         length_attr(mask, "width", vw, 1.2 * vw),
                                         length_attr(mask, "height", vh, 1.2 * vh));
            }
            if (region.width() > 0 && region.height() > 0) {
                Affine content_m = cm;
                if (content_bbox)
                    content_m = cm * Affine::translate(box->x0, box->y0) * Affine::scale(box->width(), box->height());
                bool inner_missing = false;
                const pugi::xml_node inner = reference(mask, "mask", "mask", inner_missing);
                const bool inner_ok = inner && !is_active(inner);
                clipped(region, cm, [&] {
                    if (inner_ok) items.push_back(layer_item(Item::BeginLayer, 1));
                    Style st;
                    walk(mask, st, content_m, vw, vh, depth + 1);
                    if (inner_ok) {
                        emit_mask(inner, cm, box, vw, vh, depth + 1);
                        items.push_back(layer_item(Item::EndLayer, 1));
                    }
                });
            }
        }
        Item end;
        end.kind = Item::EndMask;
        items.push_back(std::move(end));
        active_refs.pop_back();
    }

    SvgOptions options;

    // The bytes an <image> href names: a data: URI (base64 or plain), or a relative file inside
    // the resource root; nullopt (with a warning) for anything refused or unreadable.
    std::optional<std::vector<std::uint8_t>> image_bytes(std::string_view ref) {
        ref = trim(ref);
        if (ref.substr(0, 5) == "data:") {
            const std::size_t comma = ref.find(',');
            if (comma == std::string_view::npos) return std::nullopt;
            const std::string_view meta = ref.substr(5, comma - 5);
            const std::string_view payload = ref.substr(comma + 1);
            std::vector<std::uint8_t> out;
            if (meta.size() >= 7 && meta.substr(meta.size() - 7) == ";base64") {
                unsigned acc = 0;
                int bits = 0;
                for (char ch : payload) {
                    int v;
                    if (ch >= 'A' && ch <= 'Z')
                        v = ch - 'A';
                    else if (ch >= 'a' && ch <= 'z')
                        v = ch - 'a' + 26;
                    else if (ch >= '0' && ch <= '9')
                        v = ch - '0' + 52;
                    else if (ch == '+' || ch == '-')
                        v = 62;
                    else if (ch == '/' || ch == '_')
                        v = 63;
                    else
                        continue;  // whitespace, padding
                    acc = (acc << 6) | static_cast<unsigned>(v);
                    bits += 6;
                    if (bits >= 8) {
                        bits -= 8;
                        out.push_back(static_cast<std::uint8_t>(acc >> bits));
                        acc &= (1u << bits) - 1;
                    }
                }
            } else {
                out.assign(payload.begin(), payload.end());
            }
            return out;
        }
        if (ref.find(':') != std::string_view::npos || ref.empty() || ref.front() == '/' || ref.front() == '#') {
            warn("image '" + std::string(ref.substr(0, 80)) + "' refused: only data: URIs and relative files are read");
            return std::nullopt;
        }
        if (options.base_dir.empty()) {
            warn("image '" + std::string(ref) + "' refused: the document has no folder to resolve it against");
            return std::nullopt;
        }
        namespace fs = std::filesystem;
        std::error_code ec;
        const fs::path root =
            fs::weakly_canonical(options.resource_root.empty() ? options.base_dir : options.resource_root, ec);
        const fs::path file = fs::weakly_canonical(fs::path(options.base_dir) / std::string(ref), ec);
        const std::string r = root.string(), f = file.string();
        if (ec || r.empty() || f.size() <= r.size() || f.compare(0, r.size(), r) != 0 ||
            (f[r.size()] != '/' && r.back() != '/')) {
            warn("image '" + std::string(ref) + "' refused: outside the document's folder");
            return std::nullopt;
        }
        try {
            return read_file(f);
        } catch (const Error& e) {
            warn(std::string("image: ") + e.what());
            return std::nullopt;
        }
    }

    void image(const pugi::xml_node& n, const Style& st, const Affine& cm, double vw, double vh, double opacity) {
        if (!st.visible) return;
        const std::optional<std::vector<std::uint8_t>> bytes = image_bytes(href(n));
        if (!bytes) return;
        std::shared_ptr<const Pixmap> raster;
        std::shared_ptr<const SvgDocument> svg;
        double iw = 0, ih = 0;
        try {
            if (sniff_image(*bytes) == ImageFormat::Svg) {
                if (options.nesting + 1 > limits_.svg_image_nesting) {
                    warn("SVG images nested deeper than " + std::to_string(limits_.svg_image_nesting) + "; skipped");
                    return;
                }
                SvgOptions inner = options;
                inner.nesting++;
                svg = std::make_shared<const SvgDocument>(SvgDocument::parse(
                    std::string_view(reinterpret_cast<const char*>(bytes->data()), bytes->size()), inner));
                // Its warnings are this document's too (a skipped image deep in a chain, a bad
                // path inside an icon): the reader of this file would otherwise never see them.
                for (const std::string& w : svg->warnings()) warn("in an SVG image: " + w);
                iw = svg->intrinsic_width();
                ih = svg->intrinsic_height();
            } else {
                raster = std::make_shared<const Pixmap>(decode_image(*bytes));
                iw = raster->width();
                ih = raster->height();
            }
        } catch (const Error& e) {
            warn(std::string("image not drawn: ") + e.what());
            return;
        }
        auto size_attr = [&](const char* name, double percent_of) -> std::optional<double> {
            std::string_view v = trim(n.attribute(name).value());
            for (const auto& [k, val] : properties(n))
                if (k == name) v = trim(val);
            if (v.empty() || v == "auto") return std::nullopt;
            return parse_length(v, percent_of);
        };
        std::optional<double> w = size_attr("width", vw), h = size_attr("height", vh);
        if (!w && !h) {
            w = iw;
            h = ih;
        } else if (!w) {
            w = *h * iw / ih;
        } else if (!h) {
            h = *w * ih / iw;
        }
        if (!(*w > 0) || !(*h > 0) || !(iw > 0) || !(ih > 0)) return;
        const double x = length_attr(n, "x", vw), y = length_attr(n, "y", vh);
        const std::string_view par = n.attribute("preserveAspectRatio").value();
        const Affine m = cm * Affine::translate(x, y) * viewbox_transform(Rect::from_xywh(0, 0, iw, ih), par, *w, *h);
        const bool slice = par.find("slice") != std::string_view::npos;
        const std::string rendering = inherited(n, "image-rendering");
        const bool smooth = !(rendering == "optimizeSpeed" || rendering == "pixelated" || rendering == "crisp-edges");
        auto draw = [&] {
            Item it;
            it.transform = m;
            it.opacity = opacity;
            if (svg) {
                it.kind = Item::SvgImage;
                it.svg_image = svg;
            } else {
                it.kind = Item::Fill;
                it.path.add_rect(Rect::from_xywh(0, 0, iw, ih));
                it.shader = std::make_shared<const Shader>(Shader::image(raster, smooth));
            }
            items.push_back(std::move(it));
        };
        if (slice || svg)
            clipped(Rect::from_xywh(x, y, *w, *h), cm, draw);
        else
            draw();
    }

    int paint_depth = 0;  // patterns inside pattern content

    // A pattern with its href chain (attributes from the first element that has them, content
    // from the first with child elements): its tile content becomes a PatternTile that the
    // renderer draws at device resolution and repeats through an image shader.
    bool pattern(const pugi::xml_node& node, const Path& path, double vw, double vh, Item& it) {
        std::vector<pugi::xml_node> chain{node};
        while (chain.size() < 32) {
            const char* h = href(chain.back());
            if (*h != '#') break;
            const pugi::xml_node next = lookup(h + 1);
            if (!next || std::string_view(next.name()) != "pattern") break;
            if (std::find(chain.begin(), chain.end(), next) != chain.end()) break;
            chain.push_back(next);
        }
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
        if (!content || is_active(node) || is_active(content)) return false;
        const bool units_bbox = attr("patternUnits") != "userSpaceOnUse";
        const bool content_bbox = attr("patternContentUnits") == "objectBoundingBox";
        const Rect b = path.bounds();
        const bool have_box = b.width() > 0 && b.height() > 0;
        if ((units_bbox || content_bbox) && !have_box) return false;
        auto num = [&](const char* name, double percent_of) -> double {
            const std::string_view v = attr(name);
            if (v.empty()) return 0;
            auto l = parse_length(v, units_bbox ? 1.0 : percent_of);
            return l ? *l : 0;
        };
        Rect tile;
        if (units_bbox)
            tile = Rect::from_xywh(b.x0 + num("x", 1) * b.width(), b.y0 + num("y", 1) * b.height(),
                                   num("width", 1) * b.width(), num("height", 1) * b.height());
        else
            tile = Rect::from_xywh(num("x", vw), num("y", vh), num("width", vw), num("height", vh));
        if (!(tile.width() > 0) || !(tile.height() > 0) || !std::isfinite(tile.width()) ||
            !std::isfinite(tile.height()))
            return false;
        Affine pt;
        if (const std::string_view t = attr("patternTransform"); !t.empty()) {
            try {
                pt = parse_svg_transform(t);
                if (!pt.inverse()) return false;
                pt = with_origin(node, pt, vw, vh);
            } catch (const Error&) { warn("invalid patternTransform; ignored"); }
        }
        Affine cm;
        double cvw = vw, cvh = vh;
        const pugi::xml_node vb_node = [&] {
            for (const pugi::xml_node& n : chain)
                if (*n.attribute("viewBox").value()) return n;
            return pugi::xml_node();
        }();
        if (auto vb = vb_node ? parse_viewbox(vb_node.attribute("viewBox").value()) : std::nullopt) {
            cm = Affine::translate(tile.x0, tile.y0) *
                 viewbox_transform(*vb, vb_node.attribute("preserveAspectRatio").value(), tile.width(), tile.height());
            cvw = vb->width();
            cvh = vb->height();
        } else {
            // The content's origin is the tile's top-left corner.
            cm = Affine::translate(tile.x0, tile.y0);
            if (content_bbox) cm = cm * Affine::scale(b.width(), b.height());
        }
        if (++paint_depth > limits_.nesting_depth)
            throw Error(ErrorKind::Limit, "patterns nested deeper than " + std::to_string(limits_.nesting_depth));
        std::vector<Item> saved;
        std::swap(saved, items);
        active_refs.push_back(node);
        active_refs.push_back(content);
        Style st;
        apply_style(content, st);
        try {
            walk(content, st, cm, cvw, cvh, 1);
        } catch (...) {
            std::swap(saved, items);
            throw;
        }
        active_refs.pop_back();
        active_refs.pop_back();
        --paint_depth;
        auto tile_items = std::make_shared<PatternTile>();
        tile_items->items = std::move(items);
        tile_items->tile = tile;
        tile_items->transform = pt;
        items = std::move(saved);
        it.pattern = std::move(tile_items);
        return true;
    }

    void element(const pugi::xml_node& child, const Style& st, const Affine& m, double vw, double vh, int depth) {
        if (depth > limits_.nesting_depth)
            throw Error(ErrorKind::Limit, "SVG elements nested deeper than " + std::to_string(limits_.nesting_depth));
        if (++expanded > limits_.svg_elements)
            throw Error(ErrorKind::Limit, "SVG expands to more than " + std::to_string(limits_.svg_elements) +
                                              " elements (nested <use> references)");
        const std::string_view name = child.name();
        if (name == "defs" || name == "title" || name == "desc" || name == "metadata" || name == "style" ||
            name == "clipPath" || name == "mask" || name == "pattern" || name == "linearGradient" ||
            name == "radialGradient" || name == "symbol" || name == "marker" || name == "filter")
            return;
        Style cst = st;
        cst.viewport_w = vw;
        cst.viewport_h = vh;
        apply_style(child, cst);
        for (const auto& [k, v] : properties(child))
            if (k == "display" && trim(v) == "none") return;
        Affine cm = m;
        if (const char* t = child.attribute("transform").value(); *t) {
            try {
                cm = m * with_origin(child, parse_svg_transform(t), vw, vh);
            } catch (const Error& e) {
                warn(std::string("<") + child.name() + ">: " + e.what() + "; element skipped");
                return;
            }
        }
        double opacity = 1;
        for (const auto& [k, v] : properties(child))
            if (k == "opacity")
                if (auto ov = parse_opacity(v)) opacity = *ov;
        if (opacity <= 0) {
            // Not drawn, but it still counts in its group's bounding box: its content's box.
            const std::size_t first = items.size();
            content(child, cst, cm, vw, vh, depth, 1.0);
            const std::optional<Rect> box = items_bbox(first, cm);
            items.resize(first);
            if (box) items.push_back(bounds_item(Path().add_rect(*box), cm));
            return;
        }
        bool clip_missing = false, mask_missing = false;
        const pugi::xml_node clip = reference(child, "clip-path", "clipPath", clip_missing);
        const pugi::xml_node mask = reference(child, "mask", "mask", mask_missing);
        (void)clip_missing;  // a clip-path or mask naming nothing is ignored (as browsers do)
        (void)mask_missing;
        if ((clip && is_active(clip)) || (mask && is_active(mask))) {
            warn(std::string("<") + child.name() + ">: recursive clip-path or mask; element not drawn");
            return;
        }
        BlendMode blend = BlendMode::Normal;
        bool isolate = false;
        for (const auto& [k, v] : properties(child)) {
            if (k == "mix-blend-mode") parse_blend_mode(trim(v), blend);
            if (k == "isolation") isolate = trim(v) == "isolate";
        }
        std::optional<std::vector<svg_filter::FilterRef>> frefs = filter_refs(child);
        std::vector<pugi::xml_node> filter_nodes;
        if (frefs) {
            // An invalid filter function makes the whole property invalid (ignored); a url naming
            // no filter hides the element when it stands alone and is skipped in a list (as resvg).
            const svg_filter::SvgFilterEnv env = filter_env(cst, vw, vh, depth);
            const bool bad_function = std::any_of(frefs->begin(), frefs->end(), [&](const svg_filter::FilterRef& r) {
                return r.url.empty() && !svg_filter::build_function(r, std::nullopt, env);
            });
            if (bad_function) {
                warn(std::string("<") + child.name() + ">: invalid filter function; filter ignored");
                frefs.reset();
            }
        }
        if (frefs) {
            std::vector<svg_filter::FilterRef> kept;
            for (const svg_filter::FilterRef& r : *frefs) {
                if (!r.url.empty()) {
                    const pugi::xml_node f = lookup(r.url);
                    if (!f || std::string_view(f.name()) != "filter") {
                        if (frefs->size() == 1) return;
                        continue;
                    }
                    filter_nodes.push_back(f);
                }
                kept.push_back(r);
            }
            *frefs = std::move(kept);
        }
        if (std::any_of(filter_nodes.begin(), filter_nodes.end(),
                        [&](const pugi::xml_node& f) { return is_active(f); })) {
            // Drawn inside its own filter (through feImage): drawn without the filter.
            warn(std::string("<") + child.name() + ">: recursive filter ignored");
            frefs.reset();
            filter_nodes.clear();
        }
        const bool layered = opacity < 1 || clip || mask || blend != BlendMode::Normal || isolate || frefs;
        const std::size_t first = items.size();
        if (layered) {
            Item begin = layer_item(Item::BeginLayer, opacity);
            begin.blend = blend;
            items.push_back(std::move(begin));
        }
        const std::size_t filter_first = items.size();
        if (frefs) items.push_back(layer_item(Item::BeginFilter, 1));
        active_refs.insert(active_refs.end(), filter_nodes.begin(), filter_nodes.end());
        content(child, cst, cm, vw, vh, depth, layered ? 1.0 : opacity);
        active_refs.resize(active_refs.size() - filter_nodes.size());
        if (frefs) {
            filtering.push_back(child);
            const bool outer_self_reference = filter_self_reference;
            filter_self_reference = false;
            auto graphs = build_filters(*frefs, items_bbox(filter_first + 1, cm), cst, vw, vh, depth);
            filtering.pop_back();
            const bool self_reference = filter_self_reference;
            filter_self_reference = outer_self_reference;
            if (self_reference) {
                warn(std::string("<") + child.name() + ">: feImage references the filtered element; filter ignored");
                items.erase(items.begin() + static_cast<std::ptrdiff_t>(filter_first));
                graphs.reset();
            } else if (!graphs) {
                items.resize(first);
                return;
            }
            if (graphs) {
                Item end = layer_item(Item::EndFilter, 1);
                end.transform = cm;
                end.filters = std::make_shared<const std::vector<filter::FilterGraph>>(std::move(*graphs));
                items.push_back(std::move(end));
            }
        }
        if (layered) {
            const std::optional<Rect> box = items_bbox(first + 1, cm);
            if (clip) emit_clip(clip, cm, box, vw, vh, depth);
            if (mask) emit_mask(mask, cm, box, vw, vh, depth);
            items.push_back(layer_item(Item::EndLayer, opacity));
        }
    }

    void content(const pugi::xml_node& child, const Style& cst, const Affine& cm, double vw, double vh, int depth,
                 double opacity) {
        const std::string_view name = child.name();
        const bool container = name == "g" || name == "a" || name == "switch" || name == "svg" || name == "use";
        if (container) {
            const bool layer = opacity < 1;
            if (layer) items.push_back(layer_item(Item::BeginLayer, opacity));
            if (name == "svg" && child.parent() == child.root()) {
                // The root svg: its viewport is the document's, already set up by the caller.
                walk(child, cst, cm, vw, vh, depth + 1);
            } else if (name == "svg") {
                const double w = length_attr(child, "width", vw, vw), h = length_attr(child, "height", vh, vh);
                viewport(child, cst, cm, length_attr(child, "x", vw), length_attr(child, "y", vh), w, h, depth, false);
            } else if (name == "use") {
                use(child, cst, cm, vw, vh, depth);
            } else {
                walk(child, cst, cm, vw, vh, depth + 1);
            }
            if (layer) items.push_back(layer_item(Item::EndLayer, opacity));
            return;
        }
        if (name == "image") return image(child, cst, cm, vw, vh, opacity);
        if (name == "text") return text(child, cst, cm, vw, vh, opacity);
        std::optional<Path> p = shape_path(child, vw, vh);
        if (!p) {
            if (name != "path" && name != "rect" && name != "circle" && name != "ellipse" && name != "line" &&
                name != "polyline" && name != "polygon")
                warn("<" + std::string(name) + "> is not supported; skipped");
            return;
        }
        if (p->empty()) return;
        if (!cst.visible) {
            // Hidden shapes are not drawn but still count in their group's bounding box.
            items.push_back(bounds_item(std::move(*p), cm));
            return;
        }
        // A line has no interior; a polyline fills like a polygon (closed implicitly).
        std::optional<Item> fill_item, stroke_item;
        if (Item f; name != "line" && resolve_paint(cst.fill, *p, cm, vw, vh, f)) {
            f.kind = Item::Fill;
            f.path = *p;
            f.transform = cm;
            f.rule = cst.fill_rule;
            f.opacity = cst.fill_opacity * opacity;
            fill_item = std::move(f);
        }
        const Path path_copy = *p;
        if (Item st; cst.stroke_style.width > 0 && resolve_paint(cst.stroke, *p, cm, vw, vh, st)) {
            st.kind = Item::Stroke;
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
            if (part == 0 && fill_item) items.push_back(std::move(*fill_item));
            if (part == 1 && stroke_item) items.push_back(std::move(*stroke_item));
            if (part == 2 && markable) emit_markers(path_copy, cst, cm, vw, vh, depth);
        }
    }

    // Markers at the vertices of `path`: marker-start at the first, marker-end at the last,
    // marker-mid at the others; each oriented (orient auto / auto-start-reverse / an angle),
    // scaled by the stroke width (markerUnits strokeWidth), mapped by its viewBox and refX/refY,
    // and clipped to markerWidth x markerHeight unless overflow is visible.
    void emit_markers(const Path& path, const Style& st, const Affine& cm, double vw, double vh, int depth) {
        if (st.marker_start.empty() && st.marker_mid.empty() && st.marker_end.empty()) return;
        struct Vertex {
            Point p;
            std::optional<Vec> in, out;
        };
        std::vector<Vertex> vs;
        std::size_t subpath_first = 0;
        auto dir = [](Point a, Point b) -> std::optional<Vec> {
            const Vec d{b.x - a.x, b.y - a.y};
            if (d.x == 0 && d.y == 0) return std::nullopt;
            return d;
        };
        auto segment = [&](Point p0, std::initializer_list<Point> rest) {
            std::vector<Point> pts{p0};
            pts.insert(pts.end(), rest.begin(), rest.end());
            std::optional<Vec> start, end;
            for (std::size_t i = 1; i < pts.size() && !start; ++i) start = dir(p0, pts[i]);
            for (std::size_t i = pts.size() - 1; i-- > 0 && !end;) end = dir(pts[i], pts.back());
            if (!vs.empty() && !vs.back().out) vs.back().out = start;
            vs.push_back({pts.back(), end, std::nullopt});
        };
        auto close = [&](Point last, Point first) {
            if (!(last == first)) segment(last, {first});
            // A closed subpath: its end vertex turns into its first segment, and its start vertex
            // comes in from its closing segment.
            if (subpath_first < vs.size()) {
                vs.back().out = vs[subpath_first].out;
                vs[subpath_first].in = vs.back().in;
            }
        };
        struct Visitor {
            std::function<void(Point)> on_move;
            std::function<void(Point, std::initializer_list<Point>)> on_segment;
            std::function<void(Point, Point)> on_close;
            void move(Point p) { on_move(p); }
            void line(Point a, Point b) { on_segment(a, {b}); }
            void quad(Point a, Point c, Point b) { on_segment(a, {c, b}); }
            void cubic(Point a, Point c1, Point c2, Point b) { on_segment(a, {c1, c2, b}); }
            void conic(Point a, Point c, Point b, double) { on_segment(a, {c, b}); }
            void close(Point last, Point first) { on_close(last, first); }
        };
        path.visit(Visitor{[&](Point p) {
                               subpath_first = vs.size();
                               vs.push_back({p, std::nullopt, std::nullopt});
                           },
                           segment, close});
        if (vs.empty()) return;
        std::shared_ptr<const ContextElement> context;  // the marked shape, for context-fill/-stroke
        for (std::size_t i = 0; i < vs.size(); ++i) {
            const std::string& id = i == 0 ? st.marker_start : i + 1 == vs.size() ? st.marker_end : st.marker_mid;
            if (id.empty()) continue;
            const pugi::xml_node marker = lookup(id);
            if (!marker || std::string_view(marker.name()) != "marker" || is_active(marker)) continue;
            const Vertex& v = vs[i];
            double angle = 0;
            const std::string_view orient = trim(marker.attribute("orient").value());
            if (orient == "auto" || orient == "auto-start-reverse") {
                const std::optional<Vec>& a = v.in ? v.in : v.out;
                const std::optional<Vec>& b = v.out ? v.out : v.in;
                if (a && b) {
                    const double ai = std::atan2(a->y, a->x), ao = std::atan2(b->y, b->x);
                    angle = (ai + ao) / 2;
                    if (std::fabs(ai - ao) > kPi) angle += kPi;
                }
                if (orient == "auto-start-reverse" && i == 0) angle += kPi;
            } else if (!orient.empty()) {
                std::string_view o = orient;
                double unit = kPi / 180;
                if (o.size() > 3 && o.substr(o.size() - 3) == "deg")
                    o.remove_suffix(3);
                else if (o.size() > 3 && o.substr(o.size() - 3) == "rad") {
                    o.remove_suffix(3);
                    unit = 1;
                } else if (o.size() > 4 && o.substr(o.size() - 4) == "grad") {
                    o.remove_suffix(4);
                    unit = kPi / 200;
                } else if (o.size() > 4 && o.substr(o.size() - 4) == "turn") {
                    o.remove_suffix(4);
                    unit = 2 * kPi;
                }
                if (auto n = parse_number(o)) angle = *n * unit;
            }
            if (!context) context = std::make_shared<const ContextElement>(ContextElement{path, cm, vw, vh});
            emit_marker(marker, st, context, cm * Affine::translate(v.p.x, v.p.y) * Affine::rotate(angle), vw, vh,
                        depth);
        }
    }

    // The overflow `n` sets itself ("inherit" included), empty when it sets none.
    std::string own_overflow(const pugi::xml_node& n) {
        std::string out;
        for (const auto& [k, v] : properties(n))
            if (k == "overflow") out = std::string(trim(v));
        return out;
    }

    // `paint` as the context paint of an element drawn with `context`: a paint server keeps the
    // context element it already has (a context paint passed on), or takes `context`.
    static PaintRef context_paint(PaintRef paint, const std::shared_ptr<const ContextElement>& context) {
        if (paint.kind == PaintRef::Server && !paint.context) paint.context = context;
        return paint;
    }

    void emit_marker(const pugi::xml_node& marker, const Style& st,
                     const std::shared_ptr<const ContextElement>& context, const Affine& at, double vw, double vh,
                     int depth) {
        double scale = 1;
        if (std::string_view(marker.attribute("markerUnits").value()) != "userSpaceOnUse")
            scale = st.stroke_style.width;
        if (!(scale > 0)) return;
        const double mw = length_attr(marker, "markerWidth", vw, 3), mh = length_attr(marker, "markerHeight", vh, 3);
        if (!(mw > 0) || !(mh > 0)) return;
        Affine vbt;
        double nvw = mw, nvh = mh;
        if (auto vb = parse_viewbox(marker.attribute("viewBox").value())) {
            vbt = viewbox_transform(*vb, marker.attribute("preserveAspectRatio").value(), mw, mh);
            nvw = vb->width();
            nvh = vb->height();
        }
        const Point ref = vbt.apply({length_attr(marker, "refX", nvw), length_attr(marker, "refY", nvh)});
        const Affine box = at * Affine::scale(scale) * Affine::translate(-ref.x, -ref.y);
        const Affine content_m = box * vbt;
        // overflow: hidden unless set (the user agent style of marker); `inherit` takes the
        // parent's computed value: what it sets, or the initial value visible when it sets none.
        std::string overflow = own_overflow(marker);
        for (pugi::xml_node a = marker.parent(); overflow == "inherit"; a = a.parent()) {
            overflow = a && a.type() == pugi::node_element ? own_overflow(a) : "";
            if (overflow.empty()) overflow = "visible";
        }
        const bool clip = !(overflow == "visible" || overflow == "auto");
        active_refs.push_back(marker);
        Style mst;
        mst.context_fill = context_paint(st.fill, context);
        mst.context_stroke = context_paint(st.stroke, context);
        apply_style(marker, mst);
        items.push_back(layer_item(Item::BeginLayer, 1));
        walk(marker, mst, content_m, nvw, nvh, depth + 1);
        if (clip) {
            Item begin;
            begin.kind = Item::BeginClip;
            items.push_back(std::move(begin));
            Item r;
            r.kind = Item::Fill;
            r.path.add_rect(Rect::from_xywh(0, 0, mw, mh));
            r.transform = box;
            items.push_back(std::move(r));
            Item end;
            end.kind = Item::EndMask;
            items.push_back(std::move(end));
        }
        items.push_back(layer_item(Item::EndLayer, 1));
        active_refs.pop_back();
    }

    // ---- Text (src/formats/svg_text.hpp): text, tspan, tref, textPath and a inside text become
    // glyph outlines in the text's user space, painted as ordinary fill and stroke items.

    std::unique_ptr<svg_text::FontSet> font_set;
    std::size_t text_chars_total = 0;  // characters of all text laid out so far (use copies too)

    svg_text::FontSet* text_fonts() {
        if (!font_set) {
            std::shared_ptr<const FontDatabase> db = options.font_database;
            if (!db) {
                FontDatabaseOptions fo;
                fo.font_dirs = options.font_dirs;
                fo.font_files = options.font_files;
                fo.system_fonts = options.system_fonts;
                db = std::make_shared<const FontDatabase>(fo);
                options.font_database = db;  // nested SVG images share it
            }
            font_set = std::make_unique<svg_text::FontSet>(db, options.system_fallback);
        }
        return font_set.get();
    }

    // Computed text properties along the text/tspan tree.
    struct TextCtx {
        svg_text::FontSpec font;
        bool small_caps = false, no_kerning = false;
        std::vector<std::string> feature_settings;
        double letter_spacing = 0, word_spacing = 0;
        svg_text::Anchor anchor = svg_text::Anchor::Start;
        svg_text::Baseline dominant = svg_text::Baseline::Alphabetic;
        svg_text::Baseline baseline = svg_text::Baseline::Alphabetic;  // alignment-baseline or dominant
        std::vector<svg_text::Span::Shift> baseline_shifts;
        bool preserve = false;
        std::vector<svg_text::Decoration> decorations;
        int path = -1, path_element = -1;
        std::size_t style = 0;
        std::string direction;
        double viewport_width = 100;  // percentages of letter- and word-spacing (as resvg)
    };

    static std::vector<std::string_view> split_list(std::string_view v) {
        std::vector<std::string_view> out;
        std::size_t i = 0;
        while (i < v.size()) {
            while (i < v.size() && (std::isspace(static_cast<unsigned char>(v[i])) || v[i] == ',')) ++i;
            const std::size_t b = i;
            while (i < v.size() && !std::isspace(static_cast<unsigned char>(v[i])) && v[i] != ',') ++i;
            if (i > b) out.push_back(v.substr(b, i - b));
        }
        return out;
    }

    // A length for text properties: em and ex relative to `font_size`, percentages of `percent_of`.
    static std::optional<double> text_length(std::string_view v, double font_size, double percent_of) {
        v = trim(v);
        if (v.size() > 2 && v.substr(v.size() - 2) == "em") {
            auto n = parse_number(v.substr(0, v.size() - 2));
            return n ? std::optional<double>(*n * font_size) : std::nullopt;
        }
        if (v.size() > 2 && v.substr(v.size() - 2) == "ex") {
            auto n = parse_number(v.substr(0, v.size() - 2));
            return n ? std::optional<double>(*n * font_size / 2) : std::nullopt;
        }
        return parse_length(v, percent_of);
    }

    std::string generic_family(std::string_view f) const {
        if (f == "serif") return options.serif_family;
        if (f == "sans-serif") return options.sans_serif_family;
        if (f == "cursive") return options.cursive_family;
        if (f == "fantasy") return options.fantasy_family;
        if (f == "monospace") return options.monospace_family;
        return std::string(f);
    }

    void apply_font_family(std::string_view v, TextCtx& ctx) {
        std::vector<std::string> fams;
        std::size_t i = 0;
        while (i <= v.size()) {
            std::size_t comma = v.find(',', i);
            if (comma == std::string_view::npos) comma = v.size();
            std::string_view f = trim(v.substr(i, comma - i));
            if (f.size() >= 2 && (f.front() == '\'' || f.front() == '"') && f.back() == f.front())
                f = f.substr(1, f.size() - 2);
            if (!f.empty()) fams.push_back(generic_family(f));
            i = comma + 1;
        }
        if (!fams.empty()) ctx.font.families = std::move(fams);
    }

    // font-feature-settings and font-variation-settings: a comma-separated list of a quoted tag
    // and an optional value ("'liga' 0, 'smcp'"), as (tag, value) pairs without the quotes.
    static std::vector<std::pair<std::string, std::string>> tag_value_list(std::string_view v) {
        std::vector<std::pair<std::string, std::string>> out;
        std::size_t i = 0;
        while (i <= v.size()) {
            std::size_t comma = v.find(',', i);
            if (comma == std::string_view::npos) comma = v.size();
            std::string item(trim(v.substr(i, comma - i)));
            std::erase(item, '"');
            std::erase(item, '\'');
            const std::size_t sp = item.find(' ');
            if (!item.empty())
                out.emplace_back(item.substr(0, sp), sp == std::string::npos
                                                         ? std::string()
                                                         : std::string(trim(std::string_view(item).substr(sp))));
            i = comma + 1;
        }
        return out;
    }

    static std::optional<int> font_weight(std::string_view v, int parent) {
        if (v == "normal") return 400;
        if (v == "bold") return 700;
        if (v == "bolder") return parent < 350 ? 400 : parent < 550 ? 700 : 900;
        if (v == "lighter") return parent < 550 ? 100 : parent < 750 ? 400 : 700;
        if (auto n = parse_number(v); n && *n >= 1 && *n <= 1000) return static_cast<int>(std::lround(*n));
        return std::nullopt;
    }

    static std::optional<double> font_stretch(std::string_view v) {
        static const std::pair<std::string_view, double> names[] = {
            {"ultra-condensed", 50},  {"extra-condensed", 62.5}, {"condensed", 75},
            {"semi-condensed", 87.5}, {"normal", 100},           {"semi-expanded", 112.5},
            {"expanded", 125},        {"extra-expanded", 150},   {"ultra-expanded", 200}};
        for (const auto& [k, p] : names)
            if (v == k) return p;
        if (!v.empty() && v.back() == '%')
            if (auto n = parse_number(v.substr(0, v.size() - 1)); n && *n >= 0) return *n;
        return std::nullopt;
    }

    static std::optional<double> font_size(std::string_view v, double parent) {
        static const std::pair<std::string_view, int> names[] = {{"xx-small", -3}, {"x-small", -2}, {"small", -1},
                                                                 {"medium", 0},    {"large", 1},    {"x-large", 2},
                                                                 {"xx-large", 3},  {"xxx-large", 4}};
        for (const auto& [k, e] : names)
            if (v == k) return 12.0 * std::pow(1.2, e);
        if (v == "larger") return parent * 1.2;
        if (v == "smaller") return parent / 1.2;
        auto l = text_length(v, parent, parent);
        if (l && *l >= 0) return l;
        return std::nullopt;
    }

    static svg_text::Baseline baseline_kind(std::string_view v, svg_text::Baseline fallback) {
        using B = svg_text::Baseline;
        if (v == "middle") return B::Middle;
        if (v == "central") return B::Central;
        if (v == "hanging") return B::Hanging;
        if (v == "mathematical") return B::Mathematical;
        if (v == "text-before-edge" || v == "text-top" || v == "before-edge") return B::TextTop;
        if (v == "text-after-edge" || v == "text-bottom" || v == "after-edge") return B::TextBottom;
        if (v == "ideographic") return B::Ideographic;
        if (v == "alphabetic") return B::Alphabetic;
        return fallback;
    }

    // The `font` shorthand: [style] [variant] [weight] [stretch] size[/line-height] family-list.
    // An invalid value (no size, a size without a unit, no family) changes nothing; a valid one
    // resets the style, weight, stretch and variant it does not give.
    void apply_font_shorthand(std::string_view v, TextCtx& ctx, double parent_size) {
        TextCtx t = ctx;
        t.font.slant = FontSlant::Normal;
        t.font.weight = 400;
        t.font.stretch = 100;
        t.small_caps = false;
        std::size_t i = 0;
        while (i < v.size()) {
            while (i < v.size() && std::isspace(static_cast<unsigned char>(v[i]))) ++i;
            std::size_t e = i;
            while (e < v.size() && !std::isspace(static_cast<unsigned char>(v[e]))) ++e;
            const std::string_view w = v.substr(i, e - i);
            if (w.empty()) return;
            if (w == "italic")
                t.font.slant = FontSlant::Italic;
            else if (w == "oblique")
                t.font.slant = FontSlant::Oblique;
            else if (w == "small-caps")
                t.small_caps = true;
            else if (w == "normal") {
            } else if (w == "bold" || w == "bolder" || w == "lighter") {
                t.font.weight = *font_weight(w, ctx.font.weight);
            } else if (auto fs = font_stretch(w)) {
                t.font.stretch = *fs;
            } else {
                const std::string_view size = w.substr(0, w.find('/'));
                const bool bare_number = parse_number(size).has_value();
                if (bare_number && w.find('/') == std::string_view::npos && e < v.size()) {
                    // A bare number before the size is a weight; a bare number as the size is invalid.
                    auto fw = font_weight(w, ctx.font.weight);
                    std::size_t n = e;
                    while (n < v.size() && std::isspace(static_cast<unsigned char>(v[n]))) ++n;
                    std::size_t ne = n;
                    while (ne < v.size() && !std::isspace(static_cast<unsigned char>(v[ne]))) ++ne;
                    const std::string_view next = v.substr(n, ne - n).substr(0, v.substr(n, ne - n).find('/'));
                    if (fw && !next.empty() && font_size(next, parent_size) && !parse_number(next)) {
                        t.font.weight = *fw;
                        i = e;
                        continue;
                    }
                    return;
                }
                if (bare_number && *parse_number(size) != 0) return;
                auto fsz = font_size(size, parent_size);
                if (!fsz) return;
                const std::string_view family = trim(v.substr(e));
                if (family.empty()) return;
                t.font.size = *fsz;
                apply_font_family(family, t);
                ctx = t;
                return;
            }
            i = e;
        }
    }

    // Applies the text properties `node` sets itself to `ctx` (inherited ones carry on to children).
    void apply_text_props(const pugi::xml_node& node, TextCtx& ctx) {
        const double parent_size = ctx.font.size;
        ctx.baseline = ctx.dominant;
        for (const auto& [k, v] : properties(node)) {
            const std::string_view val = trim(v);
            if (val == "inherit") continue;
            if (k == "font")
                apply_font_shorthand(val, ctx, parent_size);
            else if (k == "font-size") {
                if (auto s = font_size(val, parent_size)) ctx.font.size = *s;
            }
        }
        const double fs = ctx.font.size;
        for (const auto& [k, v] : properties(node)) {
            const std::string_view val = trim(v);
            if (val == "inherit") continue;
            if (k == "font-family")
                apply_font_family(val, ctx);
            else if (k == "font-weight") {
                if (auto w = font_weight(val, ctx.font.weight)) ctx.font.weight = *w;
            } else if (k == "font-style") {
                if (val == "normal")
                    ctx.font.slant = FontSlant::Normal;
                else if (val == "italic")
                    ctx.font.slant = FontSlant::Italic;
                else if (val.substr(0, 7) == "oblique")
                    ctx.font.slant = FontSlant::Oblique;
            } else if (k == "font-stretch") {
                if (auto s = font_stretch(val)) ctx.font.stretch = *s;
            } else if (k == "font-variant" || k == "font-variant-caps") {
                ctx.small_caps = val == "small-caps";
            } else if (k == "font-kerning") {
                // A CSS property only (resvg ignores the presentation attribute).
                if (!node.attribute("font-kerning")) ctx.no_kerning = val == "none";
            } else if (k == "kerning") {
                // SVG 1.1: "auto" or a length; 0 turns kerning off, other lengths are not supported.
                if (val == "auto")
                    ctx.no_kerning = false;
                else if (auto l = parse_length(val, 1); l && *l == 0)
                    ctx.no_kerning = true;
            } else if (k == "font-feature-settings") {
                ctx.feature_settings.clear();
                if (val != "normal") {
                    for (auto& [tag, value] : tag_value_list(val)) {
                        if (value == "on") value = "1";
                        if (value == "off") value = "0";
                        ctx.feature_settings.push_back(value.empty() ? tag : tag + "=" + value);
                    }
                }
            } else if (k == "font-variation-settings") {
                ctx.font.variations.clear();
                if (val != "normal")
                    for (const auto& [tag, value] : tag_value_list(val))
                        if (auto n = parse_number(value); n && tag.size() <= 4)
                            ctx.font.variations.push_back({tag, *n});
            } else if (k == "letter-spacing") {
                if (val == "normal")
                    ctx.letter_spacing = 0;
                else if (auto l = text_length(val, fs, ctx.viewport_width))
                    ctx.letter_spacing = *l;
            } else if (k == "word-spacing") {
                if (val == "normal")
                    ctx.word_spacing = 0;
                else if (auto l = text_length(val, fs, ctx.viewport_width))
                    ctx.word_spacing = *l;
            } else if (k == "text-anchor") {
                if (val == "start")
                    ctx.anchor = svg_text::Anchor::Start;
                else if (val == "middle")
                    ctx.anchor = svg_text::Anchor::Middle;
                else if (val == "end")
                    ctx.anchor = svg_text::Anchor::End;
            } else if (k == "dominant-baseline") {
                ctx.dominant = baseline_kind(val, svg_text::Baseline::Alphabetic);
                ctx.baseline = ctx.dominant;
            } else if (k == "alignment-baseline") {
                ctx.baseline = baseline_kind(val, ctx.dominant);
            } else if (k == "baseline-shift" && std::string_view(node.name()) != "text") {
                // Not on the text element itself (as resvg): only tspans shift their baseline.
                if (val == "sub")
                    ctx.baseline_shifts.push_back({1, 0});
                else if (val == "super")
                    ctx.baseline_shifts.push_back({2, 0});
                else if (val != "baseline")
                    if (auto l = text_length(val, fs, fs)) ctx.baseline_shifts.push_back({0, *l});
            } else if (k == "text-decoration" || k == "text-decoration-line") {
                for (std::string_view w : split_list(val)) {
                    svg_text::Decoration d;
                    d.style = ctx.style;
                    if (w == "underline")
                        d.kind = svg_text::Decoration::Underline;
                    else if (w == "overline")
                        d.kind = svg_text::Decoration::Overline;
                    else if (w == "line-through")
                        d.kind = svg_text::Decoration::LineThrough;
                    else
                        continue;
                    ctx.decorations.push_back(d);
                }
            } else if (k == "direction") {
                ctx.direction = std::string(val);
            }
        }
        if (const char* sp = node.attribute("xml:space").value(); *sp)
            ctx.preserve = std::string_view(sp) == "preserve";
        ctx.font.features.clear();
        if (ctx.small_caps) ctx.font.features.push_back("smcp");
        if (ctx.no_kerning) ctx.font.features.push_back("kern=0");
        for (const std::string& f : ctx.feature_settings) ctx.font.features.push_back(f);
    }

    static constexpr std::size_t kTextElementStyle = static_cast<std::size_t>(-1);

    struct TextBuild {
        svg_text::TextInput in;
        std::vector<Style> styles;
        struct Range {
            pugi::xml_node node;
            std::size_t begin = 0, end = 0;
            double font_size = 12;
        };
        std::vector<Range> ranges;  // elements with position lists, in document order
        std::size_t chars = 0;
        bool last_space = true;       // collapsing: the text so far ends in a space (or is empty)
        bool last_preserved = false;  // the last character came from xml:space="preserve" text
        bool truncated = false;
        int path_elements = 0;
    };

    // Appends the characters of a text node under white-space processing (xml:space).
    void text_chars(std::string_view raw, const TextCtx& ctx, TextBuild& b) {
        std::u32string in = decode_utf8(raw), out;
        for (char32_t c : in) {
            if (text_chars_total + out.size() >= limits_.svg_text_chars) {
                b.truncated = true;
                break;
            }
            if (ctx.preserve) {
                // Kept as they are (newlines and tabs become spaces); a collapsible space right
                // after a preserved one still collapses.
                const char32_t k = (c == U'\n' || c == U'\r' || c == U'\t') ? U' ' : c;
                out += k;
                b.last_space = k == U' ';
                b.last_preserved = true;
                continue;
            }
            b.last_preserved = false;
            if (c == U'\n' || c == U'\r') continue;
            if (c == U'\t') c = U' ';
            if (c == U' ') {
                if (b.last_space) continue;
                b.last_space = true;
            } else {
                b.last_space = false;
            }
            out += c;
        }
        if (out.empty()) return;
        svg_text::Span sp;
        sp.style = ctx.style;
        sp.font = ctx.font;
        sp.text = std::move(out);
        sp.letter_spacing = ctx.letter_spacing;
        sp.word_spacing = ctx.word_spacing;
        sp.anchor = ctx.anchor;
        sp.baseline = ctx.baseline;
        sp.baseline_shifts = ctx.baseline_shifts;
        sp.decorations = ctx.decorations;
        sp.path = ctx.path;
        sp.path_element = ctx.path_element;
        b.chars += sp.text.size();
        text_chars_total += sp.text.size();
        b.in.spans.push_back(std::move(sp));
    }

    // The text content of an element and its descendants (for tref).
    static void all_text(const pugi::xml_node& n, std::string& out) {
        for (const pugi::xml_node& c : n.children()) {
            if (c.type() == pugi::node_pcdata || c.type() == pugi::node_cdata)
                out += c.value();
            else if (c.type() == pugi::node_element && std::string_view(c.name()) != "title" &&
                     std::string_view(c.name()) != "desc" && std::string_view(c.name()) != "metadata")
                all_text(c, out);
        }
    }

    void text_element(const pugi::xml_node& node, TextCtx ctx, const Style& parent, const Affine& text_m, double vw,
                      double vh, TextBuild& b, int depth) {
        if (depth > limits_.nesting_depth)
            throw Error(ErrorKind::Limit, "SVG elements nested deeper than " + std::to_string(limits_.nesting_depth));
        for (const auto& [k, v] : properties(node))
            if (k == "display" && trim(v) == "none") return;
        Style st = parent;
        apply_style(node, st);
        ctx.style = b.styles.size();
        b.styles.push_back(st);
        // Decorations declared outside the text element are painted with the text's own paint.
        for (svg_text::Decoration& d : ctx.decorations)
            if (d.style == kTextElementStyle) d.style = ctx.style;
        apply_text_props(node, ctx);
        const std::string_view name = node.name();
        if (name == "textPath") {
            const char* h = href(node);
            const pugi::xml_node target = *h == '#' ? lookup(h + 1) : pugi::xml_node();
            std::optional<Path> p;
            // SVG 2: any basic shape may carry the text, not only a path.
            if (target) p = shape_path(target, vw, vh);
            if (p && p->control_bounds().width() == 0 && p->control_bounds().height() == 0) p.reset();  // no length
            if (!p || p->empty()) {
                warn("<textPath> references no usable path; its text is not drawn");
                return;
            }
            Affine pt;
            if (const char* t = target.attribute("transform").value(); *t) {
                try {
                    pt = parse_svg_transform(t);
                } catch (const Error&) {}
            }
            (void)text_m;
            svg_text::TextPath tp;
            tp.path = p->transformed(pt);
            // side="right" (SVG 2) is ignored, as resvg and most browsers do.
            if (const char* so = node.attribute("startOffset").value(); *so) {
                std::string_view sv = trim(so);
                if (!sv.empty() && sv.back() == '%') {
                    if (auto pct = parse_number(sv.substr(0, sv.size() - 1))) {
                        Polyline poly;
                        try {
                            flatten(tp.path, Affine{}, 0.01, poly);
                        } catch (const Error&) {
                            poly.clear();  // an unusable path: the text is not drawn (svg_text.cpp)
                        }
                        double total = 0;
                        std::uint32_t s0 = 0;
                        for (std::size_t c = 0; c < poly.contour_count(); ++c) {
                            for (std::uint32_t i = s0 + 1; i < poly.contour_ends[c]; ++i)
                                total += std::hypot(poly.points[i].x - poly.points[i - 1].x,
                                                    poly.points[i].y - poly.points[i - 1].y);
                            s0 = poly.contour_ends[c];
                        }
                        tp.start_offset = *pct / 100 * total;
                    }
                } else if (auto l = text_length(sv, ctx.font.size, vw)) {
                    tp.start_offset = *l;
                }
            }
            ctx.path = static_cast<int>(b.in.paths.size());
            ctx.path_element = ++b.path_elements;
            b.in.paths.push_back(std::move(tp));
        }
        const std::size_t range_index = b.ranges.size();
        b.ranges.push_back({node, b.chars, b.chars, ctx.font.size});
        if (name == "tref") {
            const char* h = href(node);
            const pugi::xml_node target = *h == '#' ? lookup(h + 1) : pugi::xml_node();
            // Only SVG elements lend their text (resvg): <not-a-text> gives none.
            const std::string_view tn = target ? target.name() : "";
            if (target && (known_element(tn) || tn == "tspan" || tn == "textPath" || tn == "tref" || tn == "g")) {
                std::string s;
                all_text(target, s);
                text_chars(s, ctx, b);
            }
        } else {
            for (const pugi::xml_node& c : node.children()) {
                if (c.type() == pugi::node_pcdata || c.type() == pugi::node_cdata) {
                    text_chars(c.value(), ctx, b);
                } else if (c.type() == pugi::node_element) {
                    const std::string_view cn = c.name();
                    if (!conditions_pass(c)) continue;
                    if (cn == "tspan" || cn == "a" || cn == "tref" || (cn == "textPath" && ctx.path < 0))
                        text_element(c, ctx, st, text_m, vw, vh, b, depth + 1);
                }
            }
        }
        b.ranges[range_index].end = b.chars;
    }

    // Lays out a text element: the outlines of its spans with their styles.
    std::vector<svg_text::Outline> text_outlines(const pugi::xml_node& node, const Style& st, double vw, double vh,
                                                 std::vector<Style>& styles, std::optional<Rect>* box = nullptr) {
        TextCtx ctx;
        ctx.viewport_width = vw;
        // Inherited text properties from the ancestors, outermost first.
        std::vector<pugi::xml_node> anc;
        for (pugi::xml_node a = node.parent(); a && a.type() == pugi::node_element; a = a.parent()) anc.push_back(a);
        for (auto it = anc.rbegin(); it != anc.rend(); ++it) {
            apply_text_props(*it, ctx);
            for (svg_text::Decoration& d : ctx.decorations) d.style = kTextElementStyle;
            ctx.baseline_shifts.clear();
        }
        TextBuild b;
        text_element(node, ctx, st, Affine{}, vw, vh, b, 1);
        if (b.truncated)
            warn("the document's text holds more than " + std::to_string(limits_.svg_text_chars) +
                 " characters; the rest is not drawn");
        // A trailing collapsible space is removed.
        if (!b.in.spans.empty() && b.last_space && !b.last_preserved && !b.in.spans.back().text.empty() &&
            b.in.spans.back().text.back() == U' ') {
            b.in.spans.back().text.pop_back();
            --b.chars;
            if (b.in.spans.back().text.empty()) b.in.spans.pop_back();
        }
        for (const svg_text::Span& sp : b.in.spans) {
            if (!(sp.font.size <= limits::kMaxSvgFontSize)) {
                warn("font-size above " + std::to_string(static_cast<long long>(limits::kMaxSvgFontSize)) +
                     "; text not drawn");
                return {};
            }
        }
        if (b.chars == 0) return {};
        // Every font-family list ends with the default family.
        for (svg_text::Span& sp : b.in.spans) sp.font.families.push_back(options.font_family);
        // Position lists: outer elements first, inner ones override.
        b.in.pos.assign(b.chars, {});
        for (TextBuild::Range& r : b.ranges) {
            r.end = std::min(r.end, b.chars);  // the trailing space may have gone
            r.begin = std::min(r.begin, r.end);
            auto list = [&](const char* attr, double percent_of, std::optional<double> svg_text::CharPos::*field,
                            bool repeat_last) {
                const char* v = r.node.attribute(attr).value();
                if (!*v) return;
                std::optional<double> last;
                std::size_t i = r.begin;
                for (std::string_view w : split_list(v)) {
                    if (i >= r.end) break;
                    auto l =
                        std::string_view(attr) == "rotate" ? parse_number(w) : text_length(w, r.font_size, percent_of);
                    if (!l) return;
                    b.in.pos[i++].*field = *l;
                    last = *l;
                }
                if (repeat_last && last)
                    for (; i < r.end; ++i) b.in.pos[i].*field = *last;
            };
            list("x", vw, &svg_text::CharPos::x, false);
            list("y", vh, &svg_text::CharPos::y, false);
            list("dx", vw, &svg_text::CharPos::dx, false);
            list("dy", vh, &svg_text::CharPos::dy, false);
            list("rotate", 1, &svg_text::CharPos::rotate, true);
            if (const char* tl = r.node.attribute("textLength").value(); *tl && r.end > r.begin) {
                if (auto l = text_length(tl, r.font_size, vw); l && *l > 0)
                    b.in.lengths.push_back(
                        {r.begin, r.end, *l,
                         std::string_view(r.node.attribute("lengthAdjust").value()) == "spacingAndGlyphs"});
            }
        }
        std::string dir;
        for (const auto& [k, v] : properties(node))
            if (k == "direction") dir = std::string(trim(v));
        if (dir.empty()) dir = inherited(node, "direction");
        b.in.direction = dir == "rtl" ? TextDirection::RightToLeft : TextDirection::LeftToRight;
        std::string wm;
        for (const auto& [k, v] : properties(node))
            if (k == "writing-mode") wm = std::string(trim(v));
        if (wm.empty()) wm = inherited(node, "writing-mode");
        b.in.vertical = wm == "tb" || wm == "tb-rl" || wm == "vertical-rl" || wm == "vertical-lr";
        styles = std::move(b.styles);
        return svg_text::layout(b.in, *text_fonts(), warnings, box);
    }

    void text(const pugi::xml_node& node, const Style& st, const Affine& cm, double vw, double vh, double opacity) {
        std::vector<Style> styles;
        std::optional<Rect> cells;
        const std::vector<svg_text::Outline> outlines = text_outlines(node, st, vw, vh, styles, &cells);
        // Paint servers in objectBoundingBox units use the whole text's box (its glyph cells).
        if (!cells || outlines.empty()) return;
        Path box;
        box.add_rect(*cells);
        for (svg_text::Outline::Layer layer :
             {svg_text::Outline::Under, svg_text::Outline::Glyphs, svg_text::Outline::Over}) {
            for (const svg_text::Outline& o : outlines) {
                if (o.layer != layer || o.path.empty()) continue;
                const Style& s = styles[o.style];
                if (!s.visible) continue;
                for (int part : s.paint_order) {
                    Item it;
                    if (part == 0 && resolve_paint(s.fill, box, vw, vh, it)) {
                        it.kind = Item::Fill;
                        it.path = o.path;
                        it.transform = cm;
                        it.rule = s.fill_rule;
                        it.opacity = s.fill_opacity * opacity;
                        items.push_back(std::move(it));
                    } else if (part == 1 && s.stroke_style.width > 0 && resolve_paint(s.stroke, box, vw, vh, it)) {
                        it.kind = Item::Stroke;
                        it.stroke = s.stroke_style;
                        it.path = o.path;
                        it.transform = cm;
                        it.opacity = s.stroke_opacity * opacity;
                        items.push_back(std::move(it));
                    }
                }
            }
        }
    }
};

}  // namespace

struct SvgDocument::Impl : svg::ConvertedDocument {};

SvgDocument::SvgDocument(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
SvgDocument::SvgDocument(SvgDocument&&) noexcept = default;
SvgDocument& SvgDocument::operator=(SvgDocument&&) noexcept = default;
SvgDocument::~SvgDocument() = default;
int SvgDocument::width() const { return impl_->width; }
int SvgDocument::height() const { return impl_->height; }
double SvgDocument::intrinsic_width() const { return impl_->fwidth; }
double SvgDocument::intrinsic_height() const { return impl_->fheight; }
const std::vector<std::string>& SvgDocument::warnings() const { return impl_->warnings; }

SvgDocument SvgDocument::load(const std::string& path, const std::string& resource_root) {
    SvgOptions o;
    o.resource_root = resource_root;
    return load(path, o);
}

SvgDocument SvgDocument::load(const std::string& path, const SvgOptions& options) {
    const std::vector<std::uint8_t> bytes = read_file(path);
    SvgOptions o = options;
    std::error_code ec;
    o.base_dir = std::filesystem::absolute(std::filesystem::path(path), ec).parent_path().string();
    return parse(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), o);
}

namespace svg {

ConvertedDocument convert_document(std::string_view input, const SvgOptions& options) {
    std::string inflated;
    if (input.size() >= 2 && static_cast<unsigned char>(input[0]) == 0x1f &&
        static_cast<unsigned char>(input[1]) == 0x8b)
        inflated = gunzip(input);
    const std::string_view text = inflated.empty() ? input : std::string_view(inflated);
    ConvertedDocument out;
    pugi::xml_document xml;
    if (trim(text).empty()) throw Error(ErrorKind::Parse, "SVG input is empty");
    const pugi::xml_parse_result res = xml.load_buffer(
        text.data(), text.size(), pugi::parse_default | pugi::parse_ws_pcdata);  // text needs the spaces between tspans
    if (!res)
        throw Error(ErrorKind::Parse, std::string("malformed SVG (XML) at byte ") + std::to_string(res.offset) + ": " +
                                          res.description());
    normalise_namespaces(xml.document_element(), {});
    const pugi::xml_node root = xml.document_element();
    if (std::string_view(root.name()) != "svg")
        throw Error(ErrorKind::InvalidData, std::string("root element is <") + root.name() + ">, expected <svg>");

    const char* vb_text = root.attribute("viewBox").value();
    const std::optional<Rect> vb = parse_viewbox(vb_text);
    if (!vb && *vb_text) out.warnings.push_back(std::string("invalid viewBox '") + vb_text + "' ignored");
    auto root_length = [&](const char* name, double vb_size) -> std::optional<double> {
        const char* v = root.attribute(name).value();
        if (!*v) return std::nullopt;
        auto l = parse_length(v, vb_size);
        if (!l) throw Error(ErrorKind::InvalidData, std::string("invalid <svg> ") + name + " '" + v + "'");
        return l;
    };
    std::optional<double> w = root_length("width", vb ? vb->width() : 100);
    std::optional<double> h = root_length("height", vb ? vb->height() : 100);
    if (!w) w = vb ? vb->width() : 100.0;
    if (!h) h = vb ? vb->height() : 100.0;
    if (!(*w > 0) || !(*h > 0))
        throw Error(ErrorKind::InvalidData,
                    "SVG width and height must be positive, got " + std::to_string(*w) + " x " + std::to_string(*h));
    // The output size is the intrinsic size rounded to whole pixels (at least 1), as resvg does;
    // the fractional size stays for the scale (render() fills the whole output).
    const double rw = std::max(1.0, std::round(*w)), rh = std::max(1.0, std::round(*h));
    check_canvas_size(rw, rh);
    out.width = static_cast<int>(rw);
    out.height = static_cast<int>(rh);
    out.fwidth = *w;
    out.fheight = *h;

    // viewBox -> viewport with preserveAspectRatio.
    Affine view;
    double vw = *w, vh = *h;
    if (vb) {
        vw = vb->width();
        vh = vb->height();
        view = viewbox_transform(*vb, root.attribute("preserveAspectRatio").value(), *w, *h);
    }
    out.view = view;

    Reader reader;
    reader.options = options;
    reader.index_ids(root);
    reader.read_style_sheets(root);
    // The root goes through the element path like any group: its transform, display, opacity,
    // clip-path, mask, filter and blending apply to the whole document.
    reader.element(root, Style(), view, vw, vh, 0);
    out.items = std::move(reader.items);
    out.warnings.insert(out.warnings.end(), reader.warnings.begin(), reader.warnings.end());
    return out;
}

}  // namespace svg

SvgDocument SvgDocument::parse(std::string_view input, const SvgOptions& options) {
    auto impl = std::make_unique<Impl>();
    static_cast<svg::ConvertedDocument&>(*impl) = svg::convert_document(input, options);
    return SvgDocument(std::move(impl));
}


void SvgDocument::render(Canvas& canvas, const Affine& base) const { svg::draw(impl_->items, canvas, base); }

Pixmap SvgDocument::render() const { return render_size(impl_->width, impl_->height); }

Pixmap SvgDocument::render_size(int width, int height) const {
    Pixmap pm(width, height);
    Canvas c(pm);
    render(c, Affine::scale(width / impl_->fwidth, height / impl_->fheight));
    return pm;
}

std::pair<int, int> SvgDocument::output_size_for_width(int width) const {
    check_canvas_size(width, 1);
    const double h = std::ceil(static_cast<double>(width) * impl_->height / impl_->width);
    check_canvas_size(width, h);
    return {width, static_cast<int>(h)};
}

std::pair<int, int> SvgDocument::output_size_for_height(int height) const {
    check_canvas_size(1, height);
    const double w = std::ceil(static_cast<double>(height) * impl_->width / impl_->height);
    check_canvas_size(w, height);
    return {static_cast<int>(w), height};
}

std::pair<int, int> SvgDocument::output_size_for_zoom(double zoom) const {
    if (!(zoom > 0) || !std::isfinite(zoom)) throw Error(ErrorKind::InvalidArgument, "zoom must be positive");
    const double w = std::ceil(impl_->width * zoom), h = std::ceil(impl_->height * zoom);
    check_canvas_size(w, h);
    return {static_cast<int>(w), static_cast<int>(h)};
}

}  // namespace casteljau
