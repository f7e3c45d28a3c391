// Formats stage, SVG: the value syntaxes of values.hpp.
#include "formats/svg/values.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <string>
#include <vector>

namespace casteljau::svg {

std::string_view trim(std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    return s;
}

// A length with an optional unit; percentages resolve against `percent_of`, em against
// `font_size` and ex against half of it (as resvg: no x-height from the font), the physical units
// against `dpi`. nullopt when invalid.
std::optional<double> parse_length(std::string_view text, double percent_of, double font_size, double dpi) {
    text = trim(text);
    if (text.empty()) return std::nullopt;
    const char* b = text.data();
    const char* e = text.data() + text.size();
    if (*b == '+') ++b;
    double v;
    auto r = std::from_chars(b, e, v);
    if (r.ec != std::errc() || !std::isfinite(v)) return std::nullopt;
    const std::string_view unit(r.ptr, static_cast<std::size_t>(e - r.ptr));
    if (unit.empty() || unit == "px") return v;
    if (unit == "%") return v / 100.0 * percent_of;
    // CSS pixels scaled by dpi / 96: exactly 1 at the default resolution, so the CSS values
    // come out bit for bit as they always have.
    const double css = dpi / 96.0;
    if (unit == "pt") return v * 4.0 / 3.0 * css;
    if (unit == "pc") return v * 16.0 * css;
    if (unit == "mm") return v * 96.0 / 25.4 * css;
    if (unit == "cm") return v * 96.0 / 2.54 * css;
    if (unit == "in") return v * 96.0 * css;
    if (unit == "em") return v * font_size;
    if (unit == "ex") return v * font_size / 2;
    return std::nullopt;
}

std::optional<double> parse_number(std::string_view text) {
    text = trim(text);
    if (text.empty()) return std::nullopt;
    const char* b = text.data();
    const char* e = b + text.size();
    if (*b == '+') ++b;
    double v;
    auto r = std::from_chars(b, e, v);
    if (r.ec != std::errc() || r.ptr != e || !std::isfinite(v)) return std::nullopt;
    return v;
}

// Opacity values: a number or a percentage, clamped to [0, 1].
std::optional<double> parse_opacity(std::string_view text) {
    text = trim(text);
    if (!text.empty() && text.back() == '%') {
        auto v = parse_number(text.substr(0, text.size() - 1));
        if (!v) return std::nullopt;
        return std::clamp(*v / 100.0, 0.0, 1.0);
    }
    auto v = parse_number(text);
    if (!v) return std::nullopt;
    return std::clamp(*v, 0.0, 1.0);
}

// A viewBox "x y w h" (commas or spaces); nullopt when absent or invalid (w or h not positive).
std::optional<Rect> parse_viewbox(std::string_view text) {
    if (trim(text).empty()) return std::nullopt;
    std::string s(text);
    for (char& c : s)
        if (c == ',') c = ' ';
    double n[4];
    std::size_t pos = 0;
    for (double& x : n) {
        while (pos < s.size() && std::isspace(static_cast<unsigned char>(s[pos]))) ++pos;
        if (pos < s.size() && s[pos] == '+') ++pos;
        auto r = std::from_chars(s.data() + pos, s.data() + s.size(), x);
        if (r.ec != std::errc() || !std::isfinite(x)) return std::nullopt;
        pos = static_cast<std::size_t>(r.ptr - s.data());
    }
    if (!(n[2] > 0) || !(n[3] > 0)) return std::nullopt;
    return Rect::from_xywh(n[0], n[1], n[2], n[3]);
}

// The viewBox -> viewport (0, 0, w, h) mapping under preserveAspectRatio
// "[defer] <none | x{Min,Mid,Max}Y{Min,Mid,Max}> [meet | slice]" (default xMidYMid meet; an
// invalid value is the default).
Affine viewbox_transform(const Rect& vb, std::string_view par, double w, double h) {
    std::vector<std::string_view> words;
    for (std::string_view rest = trim(par); !rest.empty();) {
        const std::size_t sp = rest.find_first_of(" \t\r\n");
        words.push_back(rest.substr(0, sp));
        rest = sp == std::string_view::npos ? std::string_view{} : trim(rest.substr(sp));
    }
    if (!words.empty() && words.front() == "defer") words.erase(words.begin());
    std::string_view align = "xMidYMid";
    bool slice = false;
    if (!words.empty()) {
        const std::string_view a = words[0];
        const bool ok =
            a == "none" || (a.size() == 8 && a[0] == 'x' && a[4] == 'Y' &&
                            (a.substr(1, 3) == "Min" || a.substr(1, 3) == "Mid" || a.substr(1, 3) == "Max") &&
                            (a.substr(5, 3) == "Min" || a.substr(5, 3) == "Mid" || a.substr(5, 3) == "Max"));
        if (ok && words.size() <= 2 && (words.size() == 1 || words[1] == "meet" || words[1] == "slice")) {
            align = a;
            slice = words.size() == 2 && words[1] == "slice";
        }
    }
    const double sx = w / vb.width(), sy = h / vb.height();
    if (align == "none") return {sx, 0, 0, sy, -vb.x0 * sx, -vb.y0 * sy};
    const double s = slice ? std::max(sx, sy) : std::min(sx, sy);
    double tx = -vb.x0 * s, ty = -vb.y0 * s;
    const double ex = w - vb.width() * s, ey = h - vb.height() * s;
    const std::string_view xa = align.substr(1, 3), ya = align.substr(5, 3);
    if (xa == "Mid")
        tx += ex / 2;
    else if (xa == "Max")
        tx += ex;
    if (ya == "Mid")
        ty += ey / 2;
    else if (ya == "Max")
        ty += ey;
    return {s, 0, 0, s, tx, ty};
}

}  // namespace casteljau::svg
