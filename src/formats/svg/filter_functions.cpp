// Formats stage, SVG filters: the `filter` property split into its steps, and the CSS filter
// functions (blur(), drop-shadow(), grayscale(), ...) as filter graphs (filter_graphs.hpp).
#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "casteljau/error.hpp"
#include "formats/svg/filter_graphs.hpp"
#include "formats/svg/filter_values.hpp"

namespace casteljau::svg_filter {

std::optional<std::vector<FilterRef>> parse_filter_property(std::string_view value) {
    std::vector<FilterRef> out;
    std::string_view s = trim(value);
    while (!s.empty()) {
        std::size_t i = 0;
        while (i < s.size() && (std::isalnum(static_cast<unsigned char>(s[i])) || s[i] == '-')) ++i;
        if (i == 0 || i >= s.size() || s[i] != '(') return std::nullopt;
        std::string name(s.substr(0, i));
        std::transform(name.begin(), name.end(), name.begin(),
                       [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
        int depth = 0;
        std::size_t j = i;
        for (; j < s.size(); ++j) {
            if (s[j] == '(')
                ++depth;
            else if (s[j] == ')' && --depth == 0)
                break;
        }
        if (j >= s.size()) return std::nullopt;
        std::string_view inner = trim(s.substr(i + 1, j - i - 1));
        FilterRef r;
        if (name == "url") {
            if (inner.size() >= 2 && (inner.front() == '\'' || inner.front() == '"'))
                inner = inner.substr(1, inner.size() - 2);
            if (inner.empty() || inner.front() != '#') return std::nullopt;
            r.url = std::string(inner.substr(1));
        } else {
            r.function = name;
            // Arguments split at top-level whitespace and commas (rgb(...) stays whole).
            std::string cur;
            int d = 0;
            for (char c : inner) {
                if (c == '(') ++d;
                if (c == ')') --d;
                if (d == 0 && c == ',') r.commas = true;
                if (d == 0 && (std::isspace(static_cast<unsigned char>(c)) || c == ',')) {
                    if (!cur.empty()) r.args.push_back(cur);
                    cur.clear();
                } else {
                    cur += c;
                }
            }
            if (!cur.empty()) r.args.push_back(cur);
        }
        out.push_back(std::move(r));
        s = trim(s.substr(j + 1));
    }
    if (out.empty()) return std::nullopt;
    return out;
}

std::optional<filter::FilterGraph> build_function(const FilterRef& fn, const std::optional<Rect>& bbox,
                                                  const SvgFilterEnv& env) {
    using P = filter::Primitive;
    filter::FilterGraph g;
    // The region of a filter function: -10% .. 110% of the viewport in user space (as resvg
    // does), so that shadows and blurs are not cut at the element's bounding box.
    (void)bbox;
    g.region =
        Rect::from_xywh(-0.1 * env.viewport.w, -0.1 * env.viewport.h, 1.2 * env.viewport.w, 1.2 * env.viewport.h);
    P p;
    p.linear_rgb = false;
    p.subregion = g.region;
    const std::string& name = fn.function;
    if (fn.commas) return std::nullopt;
    // An amount: a number or a percentage; `def` when absent.
    auto amount = [&](double def) -> std::optional<double> {
        if (fn.args.empty()) return def;
        if (fn.args.size() > 1) return std::nullopt;
        auto v = fraction(fn.args[0]);
        if (!v || *v < 0) return std::nullopt;
        return v;
    };
    if (name == "grayscale" || name == "sepia" || name == "saturate" || name == "invert" || name == "opacity" ||
        name == "brightness" || name == "contrast") {
        auto a = amount(1);
        if (!a) return std::nullopt;
        double v = *a;
        if (name != "saturate" && name != "brightness" && name != "contrast") v = std::min(v, 1.0);
        if (name == "grayscale" || name == "sepia") {
            // The full effect's 3x3 colour matrix T, applied in proportion v: T + (1 - v) (I - T).
            static constexpr double kGray[9] = {0.2126, 0.7152, 0.0722, 0.2126, 0.7152, 0.0722, 0.2126, 0.7152, 0.0722};
            static constexpr double kSepia[9] = {0.393, 0.769, 0.189, 0.349, 0.686, 0.168, 0.272, 0.534, 0.131};
            const double* t = name == "grayscale" ? kGray : kSepia;
            p.op = P::ColorMatrix;
            p.matrix = identity_matrix();
            for (int r = 0; r < 3; ++r)
                for (int c = 0; c < 3; ++c)
                    p.matrix[static_cast<std::size_t>(r * 5 + c)] =
                        t[r * 3 + c] + (1 - v) * ((r == c ? 1.0 : 0.0) - t[r * 3 + c]);
        } else if (name == "saturate") {
            p.op = P::ColorMatrix;
            p.matrix = saturate_matrix(v);
        } else {
            p.op = P::ComponentTransfer;
            filter::TransferFunction t;
            if (name == "invert") {
                t.type = filter::TransferFunction::Table;
                t.table = {v, 1 - v};
            } else if (name == "opacity") {
                t.type = filter::TransferFunction::Table;
                t.table = {0, v};
            } else {
                t.type = filter::TransferFunction::Linear;
                t.slope = v;
                t.intercept = name == "contrast" ? 0.5 - 0.5 * v : 0;
            }
            if (name == "opacity")
                p.funcs[3] = t;
            else
                p.funcs[0] = p.funcs[1] = p.funcs[2] = t;
        }
    } else if (name == "hue-rotate") {
        double deg = 0;
        if (fn.args.size() > 1) return std::nullopt;
        if (!fn.args.empty()) {
            std::string_view a = trim(fn.args[0]);
            std::size_t k = 0;
            while (k < a.size() && (std::isdigit(static_cast<unsigned char>(a[k])) || a[k] == '.' || a[k] == '-' ||
                                    a[k] == '+' || a[k] == 'e' || a[k] == 'E'))
                ++k;
            auto v = number(a.substr(0, k));
            const std::string_view unit = a.substr(k);
            if (!v) return std::nullopt;
            // A unitless angle other than 0 is invalid CSS.
            if (unit == "deg" || (unit.empty() && *v == 0))
                deg = *v;
            else if (unit == "grad")
                deg = *v * 0.9;
            else if (unit == "rad")
                deg = *v * 180 / kPi;
            else if (unit == "turn")
                deg = *v * 360;
            else
                return std::nullopt;
        }
        p.op = P::ColorMatrix;
        p.matrix = hue_rotate_matrix(deg);
    } else if (name == "blur") {
        double sd = 0;
        if (fn.args.size() > 1) return std::nullopt;
        if (!fn.args.empty()) {
            if (trim(fn.args[0]).back() == '%') return std::nullopt;
            auto l = env.length(fn.args[0], 0);
            if (!l || *l < 0) return std::nullopt;
            sd = *l;
        }
        p.op = P::GaussianBlur;
        p.std_x = p.std_y = sd;
    } else if (name == "drop-shadow") {
        p.op = P::DropShadow;
        p.color = env.current_color;
        std::vector<double> lengths;
        bool have_color = false;
        for (const std::string& a : fn.args) {
            if (auto l = env.length(a, 0); l && trim(a).back() != '%') {
                lengths.push_back(*l);
                continue;
            }
            if (have_color) return std::nullopt;
            try {
                p.color = trim(a) == "currentColor" ? env.current_color : env.color(a);
            } catch (const Error&) { return std::nullopt; }
            have_color = true;
        }
        if (lengths.size() == 1 || lengths.size() > 3) return std::nullopt;
        p.dx = lengths.size() >= 2 ? lengths[0] : 0;
        p.dy = lengths.size() >= 2 ? lengths[1] : 0;
        p.std_x = p.std_y = lengths.size() == 3 ? std::max(0.0, lengths[2]) : 0;
        if (lengths.size() == 3 && lengths[2] < 0) return std::nullopt;
    } else {
        return std::nullopt;
    }
    g.primitives.push_back(std::move(p));
    return g;
}

}  // namespace casteljau::svg_filter
