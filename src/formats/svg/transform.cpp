// Formats stage: SVG transform lists (matrix, translate, scale, rotate, skewX, skewY).
#include <cctype>
#include <charconv>
#include <cmath>
#include <string>

#include "casteljau/error.hpp"
#include "casteljau/svg.hpp"

namespace casteljau {

Affine parse_svg_transform(std::string_view s) {
    Affine m;
    std::size_t i = 0;
    auto fail = [&](const std::string& what) -> void {
        throw Error(ErrorKind::Parse, "transform column " + std::to_string(i + 1) + ": " + what);
    };
    auto skip_ws = [&] {
        while (i < s.size() && (std::isspace(static_cast<unsigned char>(s[i])))) ++i;
    };
    auto skip_sep = [&] {
        skip_ws();
        if (i < s.size() && s[i] == ',') {
            ++i;
            skip_ws();
        }
    };
    while (true) {
        skip_sep();
        if (i >= s.size()) break;
        const std::size_t name_start = i;
        while (i < s.size() && std::isalpha(static_cast<unsigned char>(s[i]))) ++i;
        const std::string_view name = s.substr(name_start, i - name_start);
        if (name.empty()) fail("expected a transform name");
        skip_ws();
        if (i >= s.size() || s[i] != '(') fail("expected '(' after '" + std::string(name) + "'");
        ++i;
        double v[6];
        int n = 0;
        while (true) {
            skip_ws();
            if (i < s.size() && s[i] == ')') {
                ++i;
                break;
            }
            if (n > 0) skip_sep();
            if (n == 6) fail("too many numbers in " + std::string(name) + "()");
            const char* b = s.data() + i;
            const char* e = s.data() + s.size();
            if (b < e && *b == '+') ++b;
            auto r = std::from_chars(b, e, v[n]);
            if (r.ec != std::errc() || !std::isfinite(v[n])) fail("expected a number in " + std::string(name) + "()");
            i = static_cast<std::size_t>(r.ptr - s.data());
            ++n;
        }
        Affine t;
        const double deg = kPi / 180.0;
        if (name == "matrix" && n == 6)
            t = {v[0], v[1], v[2], v[3], v[4], v[5]};
        else if (name == "translate" && (n == 1 || n == 2))
            t = Affine::translate(v[0], n == 2 ? v[1] : 0);
        else if (name == "scale" && (n == 1 || n == 2))
            t = Affine::scale(v[0], n == 2 ? v[1] : v[0]);
        else if (name == "rotate" && n == 1)
            t = Affine::rotate_degrees(v[0]);
        else if (name == "rotate" && n == 3)
            t = Affine::translate(v[1], v[2]) * Affine::rotate_degrees(v[0]) * Affine::translate(-v[1], -v[2]);
        else if (name == "skewX" && n == 1)
            t = Affine::skew_x(v[0] * deg);
        else if (name == "skewY" && n == 1)
            t = Affine::skew_y(v[0] * deg);
        else
            fail("'" + std::string(name) + "' with " + std::to_string(n) + " numbers is not a transform");
        m = m * t;
    }
    return m;
}

}  // namespace casteljau
