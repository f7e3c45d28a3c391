// Formats stage, SVG filters: the value syntaxes and colour matrices of filter_values.hpp.
#include "formats/svg/filter_values.hpp"

#include <cctype>
#include <charconv>
#include <cmath>

#include "casteljau/geometry.hpp"

namespace casteljau::svg_filter {

std::string_view trim(std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    return s;
}

// Whitespace- and comma-separated numbers; nullopt when any item is not a finite number.
std::optional<std::vector<double>> numbers(std::string_view s) {
    std::vector<double> out;
    std::size_t i = 0;
    while (i < s.size()) {
        while (i < s.size() && (std::isspace(static_cast<unsigned char>(s[i])) || s[i] == ',')) ++i;
        if (i >= s.size()) break;
        const char* b = s.data() + i;
        if (*b == '+') ++b;
        double v;
        const auto r = std::from_chars(b, s.data() + s.size(), v);
        if (r.ec != std::errc() || !std::isfinite(v)) return std::nullopt;
        const std::size_t end = static_cast<std::size_t>(r.ptr - s.data());
        if (end < s.size() && !std::isspace(static_cast<unsigned char>(s[end])) && s[end] != ',') return std::nullopt;
        out.push_back(v);
        i = end;
    }
    return out;
}

std::optional<double> number(std::string_view s) {
    auto v = numbers(s);
    if (!v || v->size() != 1) return std::nullopt;
    return (*v)[0];
}

// A number or a percentage (as a fraction), for objectBoundingBox units.
std::optional<double> fraction(std::string_view s) {
    s = trim(s);
    if (s.empty()) return std::nullopt;
    if (s.back() == '%') {
        auto v = number(s.substr(0, s.size() - 1));
        if (!v) return std::nullopt;
        return *v / 100;
    }
    return number(s);
}

std::array<double, 20> identity_matrix() {
    std::array<double, 20> m{};
    m[0] = m[6] = m[12] = m[18] = 1;
    return m;
}

std::array<double, 20> saturate_matrix(double s) {
    return {0.213 + 0.787 * s,
            0.715 - 0.715 * s,
            0.072 - 0.072 * s,
            0,
            0,
            0.213 - 0.213 * s,
            0.715 + 0.285 * s,
            0.072 - 0.072 * s,
            0,
            0,
            0.213 - 0.213 * s,
            0.715 - 0.715 * s,
            0.072 + 0.928 * s,
            0,
            0,
            0,
            0,
            0,
            1,
            0};
}

std::array<double, 20> hue_rotate_matrix(double degrees) {
    const double r = degrees * kPi / 180, c = std::cos(r), s = std::sin(r);
    return {0.213 + c * 0.787 - s * 0.213,
            0.715 - c * 0.715 - s * 0.715,
            0.072 - c * 0.072 + s * 0.928,
            0,
            0,
            0.213 - c * 0.213 + s * 0.143,
            0.715 + c * 0.285 + s * 0.140,
            0.072 - c * 0.072 - s * 0.283,
            0,
            0,
            0.213 - c * 0.213 - s * 0.787,
            0.715 - c * 0.715 + s * 0.715,
            0.072 + c * 0.928 + s * 0.072,
            0,
            0,
            0,
            0,
            0,
            1,
            0};
}

std::array<double, 20> luminance_to_alpha_matrix() {
    std::array<double, 20> m{};
    m[15] = 0.2125;
    m[16] = 0.7154;
    m[17] = 0.0721;
    return m;
}

}  // namespace casteljau::svg_filter
