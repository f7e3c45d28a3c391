// Formats stage, SVG conversion: fill, stroke and the other painting properties of an element
// resolved into a Style.
#include "formats/svg/context.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace casteljau::svg {

// A fill or stroke value: none, currentColor, inherit (keeps the inherited paint), a colour,
// or url(#id) with an optional fallback (none or a colour) after it.
void apply_paint(Context& cx, const std::string& property, std::string_view value, Color current, PaintRef& paint) {
    auto simple = [&](std::string_view v, PaintRef::Kind& kind, Color& color, bool& is_current) -> bool {
        if (v == "none") {
            kind = PaintRef::None;
            return true;
        }
        if (v == "currentColor") {
            kind = PaintRef::Solid;
            color = current;
            is_current = true;
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
            warn(cx, "invalid " + property + " '" + std::string(value) + "'");
            return;
        }
        std::string_view ref = trim(value.substr(4, close - 4));
        if (ref.size() >= 2 && (ref.front() == '\'' || ref.front() == '"')) ref = ref.substr(1, ref.size() - 2);
        PaintRef p;
        p.kind = PaintRef::Server;
        p.id = ref.empty() || ref.front() != '#' ? std::string() : std::string(ref.substr(1));
        const std::string_view rest = trim(value.substr(close + 1));
        if (!rest.empty() && !simple(rest, p.fallback, p.fallback_color, p.fallback_current))
            p.fallback = PaintRef::None;
        paint = p;
        return;
    }
    PaintRef p;
    if (simple(value, p.kind, p.color, p.current))
        paint = p;
    else
        warn(cx, "invalid " + property + " '" + std::string(value) + "'");
}

namespace {

// A fill or stroke property: context-fill and context-stroke take the context element's paint.
void apply_fill_or_stroke(Context& cx, const std::string& property, std::string_view value, const Style& st,
                          PaintRef& paint) {
    if (value == "context-fill" || value == "context-stroke") {
        // The context element's paint as it used it: its currentColor is already resolved.
        paint = value == "context-fill" ? st.context_fill : st.context_stroke;
        paint.current = paint.fallback_current = false;
    } else {
        apply_paint(cx, property, value, st.color, paint);
    }
}

}  // namespace

void apply_style(Context& cx, const pugi::xml_node& node, Style& st) {
    const double font_size = font_size_of(cx, node);
    st.font_size = font_size;
    const double diag = st.viewport.diagonal();
    // `color` first so that currentColor in the same element resolves to it.
    for (const auto& [k, v] : properties(cx, node)) {
        if (k == "color") {
            try {
                st.color = parse_color(trim(v));
            } catch (const Error&) { warn(cx, "invalid color '" + v + "'"); }
        }
    }
    // An inherited currentColor paint takes this element's colour.
    for (PaintRef* p : {&st.fill, &st.stroke}) {
        if (p->current) p->color = st.color;
        if (p->fallback_current) p->fallback_color = st.color;
    }
    for (const auto& [k, v] : properties(cx, node)) {
        const std::string_view val = trim(v);
        if (k == "fill") {
            apply_fill_or_stroke(cx, k, val, st, st.fill);
        } else if (k == "fill-rule") {
            if (val == "evenodd")
                st.fill_rule = FillRule::EvenOdd;
            else if (val == "nonzero")
                st.fill_rule = FillRule::NonZero;
        } else if (k == "fill-opacity") {
            if (auto o = parse_opacity(val)) st.fill_opacity = *o;
        } else if (k == "stroke") {
            apply_fill_or_stroke(cx, k, val, st, st.stroke);
        } else if (k == "stroke-opacity") {
            if (auto o = parse_opacity(val)) st.stroke_opacity = *o;
        } else if (k == "stroke-width") {
            if (auto l = parse_length(val, diag, font_size, cx.options.dpi)) {
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
                    const std::string_view item = std::string_view(list).substr(pos, end - pos);
                    auto l = parse_length(item, diag, font_size, cx.options.dpi);
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
            if (auto l = parse_length(val, diag, font_size, cx.options.dpi)) st.stroke_style.dash_offset = *l;
        }
    }
}

// `paint` as the context paint of an element drawn with `context`: a paint server keeps the
// context element it already has (a context paint passed on), or takes `context`.
PaintRef context_paint(PaintRef paint, const std::shared_ptr<const ContextElement>& context) {
    if (paint.kind == PaintRef::Server && !paint.context) paint.context = context;
    return paint;
}

}  // namespace casteljau::svg
