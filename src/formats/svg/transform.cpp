// Formats stage: SVG transform lists (matrix, translate, scale, rotate, skewX, skewY).
#include <cctype>
#include <charconv>
#include <cmath>
#include <string>

#include "casteljau/error.hpp"
#include "casteljau/svg.hpp"

namespace casteljau {

namespace {

// Reads a transform list: names, each with its numbers in parentheses, separated by white space
// or a comma. Errors name the column.
class TransformParser {
public:
    explicit TransformParser(std::string_view s) : s_(s) {}

    Affine parse() {
        Affine m;
        for (skip_sep(); i_ < s_.size(); skip_sep()) {
            const std::string_view name = read_name();
            double v[6];
            const int n = read_numbers(name, v);
            m = m * transform(name, v, n);
        }
        return m;
    }

private:
    [[noreturn]] void fail(const std::string& what) const {
        throw Error(ErrorKind::Parse, "transform column " + std::to_string(i_ + 1) + ": " + what);
    }
    void skip_ws() {
        while (i_ < s_.size() && (std::isspace(static_cast<unsigned char>(s_[i_])))) ++i_;
    }
    void skip_sep() {
        skip_ws();
        if (i_ < s_.size() && s_[i_] == ',') {
            ++i_;
            skip_ws();
        }
    }

    // A transform's name and the '(' after it.
    std::string_view read_name() {
        const std::size_t start = i_;
        while (i_ < s_.size() && std::isalpha(static_cast<unsigned char>(s_[i_]))) ++i_;
        const std::string_view name = s_.substr(start, i_ - start);
        if (name.empty()) fail("expected a transform name");
        skip_ws();
        if (i_ >= s_.size() || s_[i_] != '(') fail("expected '(' after '" + std::string(name) + "'");
        ++i_;
        return name;
    }

    // The numbers up to ')': at most six, finite.
    int read_numbers(std::string_view name, double* v) {
        int n = 0;
        while (true) {
            skip_ws();
            if (i_ < s_.size() && s_[i_] == ')') {
                ++i_;
                return n;
            }
            if (n > 0) skip_sep();
            if (n == 6) fail("too many numbers in " + std::string(name) + "()");
            const char* b = s_.data() + i_;
            const char* e = s_.data() + s_.size();
            if (b < e && *b == '+') ++b;
            auto r = std::from_chars(b, e, v[n]);
            if (r.ec != std::errc() || !std::isfinite(v[n])) fail("expected a number in " + std::string(name) + "()");
            i_ = static_cast<std::size_t>(r.ptr - s_.data());
            ++n;
        }
    }

    // The transform `name` with its n numbers v.
    Affine transform(std::string_view name, const double* v, int n) const {
        const double deg = kPi / 180.0;
        if (name == "matrix" && n == 6) return {v[0], v[1], v[2], v[3], v[4], v[5]};
        if (name == "translate" && (n == 1 || n == 2)) return Affine::translate(v[0], n == 2 ? v[1] : 0);
        if (name == "scale" && (n == 1 || n == 2)) return Affine::scale(v[0], n == 2 ? v[1] : v[0]);
        if (name == "rotate" && n == 1) return Affine::rotate_degrees(v[0]);
        if (name == "rotate" && n == 3)
            return Affine::translate(v[1], v[2]) * Affine::rotate_degrees(v[0]) * Affine::translate(-v[1], -v[2]);
        if (name == "skewX" && n == 1) return Affine::skew_x(v[0] * deg);
        if (name == "skewY" && n == 1) return Affine::skew_y(v[0] * deg);
        fail("'" + std::string(name) + "' with " + std::to_string(n) + " numbers is not a transform");
    }

    std::string_view s_;
    std::size_t i_ = 0;
};

}  // namespace

Affine parse_svg_transform(std::string_view s) { return TransformParser(s).parse(); }

}  // namespace casteljau
