// Paint stage: CSS colour parsing (include/casteljau/paint.hpp).
//
// Grammar accepted (CSS Color Module Level 4, minus what needs a document: currentColor, system
// colours, the `none` component keyword, relative colours, colour spaces other than sRGB):
//   #rgb #rgba #rrggbb #rrggbbaa                       hex digits in any case
//   rgb(R, G, B[, A])  rgba(...)                       legacy: all numbers or all percentages
//   rgb(R G B[ / A])   rgba(...)                       modern: numbers and percentages may mix
//   hsl(H, S%, L%[, A]) hsla(...)                      legacy: S and L are percentages
//   hsl(H S L[ / A])    hsla(...)                      modern: S and L are percentages or numbers
//   a CSS named colour, `transparent`, `none`          any case
// H is a number of degrees or a dimension in deg, rad, grad or turn. A is a number in [0, 1] or a
// percentage. Out-of-range values are clamped as CSS does (R, G, B to [0, 255], percentages to
// [0%, 100%], A to [0, 1]); the hue wraps around. Function names and units are case-insensitive;
// leading and trailing whitespace is allowed.
// Rounding to 8 bits is round-half-up of value x 255 (or of the number itself for rgb() numbers):
// rgb(50%, 50%, 50%) is (128, 128, 128), an alpha of 0.5 is 128.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <string>

#include "casteljau/error.hpp"
#include "casteljau/paint.hpp"
#include "paint/named_colors.hpp"

namespace casteljau {

namespace {

constexpr bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f'; }
constexpr bool is_digit(char c) { return c >= '0' && c <= '9'; }
constexpr bool is_alpha(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }
constexpr char lower(char c) { return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c; }

bool iequals(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (lower(a[i]) != lower(b[i])) return false;
    return true;
}

int hex_value(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

// The text as it appears in an error message: at most 64 characters, control bytes shown as '?'.
std::string quoted(std::string_view text) {
    constexpr std::size_t kMax = 64;
    std::string out;
    for (std::size_t i = 0; i < text.size() && i < kMax; ++i) {
        const auto c = static_cast<unsigned char>(text[i]);
        out += (c < 0x20 || c == 0x7f) ? '?' : static_cast<char>(c);
    }
    if (text.size() > kMax) out += "...";
    return "'" + out + "'";
}

// round-half-up of v, v already clamped to [0, 255].
std::uint8_t round_byte(double v) { return static_cast<std::uint8_t>(std::floor(v + 0.5)); }

// One component inside rgb()/hsl(): a number, a percentage or a dimension (number + unit).
struct Component {
    enum class Kind { Number, Percent, Dimension } kind = Kind::Number;
    double value = 0;
    std::string_view unit;  // for Dimension
};

class Parser {
public:
    explicit Parser(std::string_view full) : full_(full) {}

    Color parse() {
        std::string_view s = full_;
        while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
        while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
        if (s.empty()) fail("empty text; expected #rgb, #rrggbb, rgb(...), hsl(...) or a CSS colour name");
        if (s.front() == '#') return parse_hex(s.substr(1));

        std::size_t n = 0;
        while (n < s.size() && (is_alpha(s[n]) || (n > 0 && (is_digit(s[n]) || s[n] == '-')))) ++n;
        const std::string_view name = s.substr(0, n);
        if (n < s.size() && s[n] == '(' && n > 0) {
            if (s.back() != ')') fail("missing ')' at the end of " + std::string(name) + "()");
            const std::string_view args = s.substr(n + 1, s.size() - n - 2);
            if (iequals(name, "rgb") || iequals(name, "rgba")) return parse_rgb(args);
            if (iequals(name, "hsl") || iequals(name, "hsla")) return parse_hsl(args);
            fail("unsupported colour function '" + std::string(name) + "()'; expected rgb(), rgba(), hsl() or hsla()");
        }
        if (n == s.size()) {
            if (iequals(s, "transparent") || iequals(s, "none")) return Color::transparent();
            if (iequals(s, "currentcolor"))
                fail(
                    "currentColor is not supported here: it depends on the element's 'color' property; "
                    "give a colour value instead");
            if (auto c = detail::find_named_color(s)) return *c;
        }
        fail("expected #rgb, #rrggbb, rgb(...), hsl(...) or a CSS colour name");
    }

private:
    [[noreturn]] void fail(const std::string& why) const {
        throw Error(ErrorKind::Parse, "invalid colour " + quoted(full_) + ": " + why);
    }

    Color parse_hex(std::string_view h) const {
        if (h.size() != 3 && h.size() != 4 && h.size() != 6 && h.size() != 8)
            fail("a hex colour needs 3, 4, 6 or 8 hex digits after '#', got " + std::to_string(h.size()));
        int v[8] = {0, 0, 0, 0, 0, 0, 0, 0};
        for (std::size_t i = 0; i < h.size(); ++i) {
            v[i] = hex_value(h[i]);
            if (v[i] < 0) {
                std::string why =
                    "'";  // built step by step: GCC 12 gives a false -Wrestrict on "'" + std::string(1, c)
                why += h[i];
                why += "' is not a hex digit";
                fail(why);
            }
        }
        auto byte = [](int hi, int lo) { return static_cast<std::uint8_t>(hi * 16 + lo); };
        if (h.size() <= 4) {  // #rgb / #rgba: each digit doubled
            return {byte(v[0], v[0]), byte(v[1], v[1]), byte(v[2], v[2]),
                    h.size() == 4 ? byte(v[3], v[3]) : std::uint8_t{255}};
        }
        return {byte(v[0], v[1]), byte(v[2], v[3]), byte(v[4], v[5]),
                h.size() == 8 ? byte(v[6], v[7]) : std::uint8_t{255}};
    }

    // --- Tokens inside the parentheses -------------------------------------------------------

    void skip_space() {
        while (pos_ < args_.size() && is_space(args_[pos_])) ++pos_;
    }
    bool at_end() const { return pos_ >= args_.size(); }
    char peek() const { return at_end() ? '\0' : args_[pos_]; }

    // A CSS <number>: [+-]? (digits (. digits)? | . digits) ([eE] [+-]? digits)?, then '%' or a unit.
    Component component(const char* what) {
        skip_space();
        const std::size_t start = pos_;
        std::size_t p = pos_;
        if (p < args_.size() && (args_[p] == '+' || args_[p] == '-')) ++p;
        const std::size_t mantissa = p;
        while (p < args_.size() && is_digit(args_[p])) ++p;
        bool digits = p > mantissa;
        if (p + 1 < args_.size() && args_[p] == '.' && is_digit(args_[p + 1])) {
            ++p;
            while (p < args_.size() && is_digit(args_[p])) ++p;
            digits = true;
        }
        if (!digits) {
            if (at_end()) fail(std::string("missing ") + what);
            std::size_t e = pos_;
            while (e < args_.size() && !is_space(args_[e]) && args_[e] != ',' && args_[e] != '/') ++e;
            if (e == pos_) e = pos_ + 1;
            const std::string_view tok = args_.substr(pos_, e - pos_);
            if (iequals(tok, "none")) fail("the 'none' keyword inside colour functions is not supported");
            fail("expected a number for " + std::string(what) + ", got '" + std::string(tok) + "'");
        }
        if (p + 1 < args_.size() && (args_[p] == 'e' || args_[p] == 'E')) {
            std::size_t q = p + 1;
            if (q < args_.size() && (args_[q] == '+' || args_[q] == '-')) ++q;
            if (q < args_.size() && is_digit(args_[q])) {
                while (q < args_.size() && is_digit(args_[q])) ++q;
                p = q;
            }
        }
        std::size_t num_begin = start;
        if (args_[num_begin] == '+') ++num_begin;  // from_chars does not take a leading '+'
        Component c;
        const auto res = std::from_chars(args_.data() + num_begin, args_.data() + p, c.value);
        if (res.ec != std::errc() || res.ptr != args_.data() + p || !std::isfinite(c.value))
            fail("number '" + std::string(args_.substr(start, p - start)) + "' for " + what + " is out of range");
        if (c.value == 0) c.value = 0;  // no negative zero
        pos_ = p;
        if (peek() == '%') {
            ++pos_;
            c.kind = Component::Kind::Percent;
        } else if (is_alpha(peek())) {
            const std::size_t u = pos_;
            while (pos_ < args_.size() && (is_alpha(args_[pos_]) || is_digit(args_[pos_]))) ++pos_;
            c.kind = Component::Kind::Dimension;
            c.unit = args_.substr(u, pos_ - u);
        }
        return c;
    }

    // Reads the component list of rgb()/hsl(): three components then an optional alpha, either
    // comma-separated (legacy) or space-separated with "/ alpha" (modern). Returns the count (3 or 4).
    int components(std::string_view fn, std::string_view args, Component out[4], bool& legacy) {
        args_ = args;
        pos_ = 0;
        static const char* const kWhat[4] = {"the first component", "the second component", "the third component",
                                             "alpha"};
        out[0] = component(kWhat[0]);
        skip_space();
        legacy = peek() == ',';
        int count = 1;
        if (legacy) {
            while (peek() == ',') {
                if (count == 4) fail(std::string(fn) + "() takes 3 components and an optional alpha, got more");
                ++pos_;
                out[count] = component(kWhat[count]);
                ++count;
                skip_space();
            }
            if (count < 3)
                fail(std::string(fn) + "() needs 3 components separated by commas, got " + std::to_string(count));
            if (peek() == '/')
                fail("'/' cannot be mixed with commas in " + std::string(fn) + "(); write " + std::string(fn) +
                     "(r, g, b, alpha) or " + std::string(fn) + "(r g b / alpha)");
        } else {
            for (; count < 3; ++count) {
                skip_space();
                if (at_end()) fail(std::string(fn) + "() needs 3 components, got " + std::to_string(count));
                if (peek() == ',') fail("commas cannot be mixed with spaces in " + std::string(fn) + "()");
                if (peek() == '/') fail(std::string(fn) + "() needs 3 components before '/'");
                out[count] = component(kWhat[count]);
            }
            skip_space();
            if (peek() == '/') {
                ++pos_;
                out[3] = component(kWhat[3]);
                count = 4;
                skip_space();
            } else if (peek() == ',') {
                fail("commas cannot be mixed with spaces in " + std::string(fn) + "()");
            }
        }
        if (!at_end()) {
            if (is_digit(peek()) || peek() == '.' || peek() == '+' || peek() == '-')
                fail(std::string(fn) + "() takes 3 components and an optional alpha, got more");
            fail("unexpected '" + std::string(args_.substr(pos_, 1)) + "' in " + std::string(fn) + "()");
        }
        return count;
    }

    std::uint8_t alpha(const Component& c) const {
        if (c.kind == Component::Kind::Dimension) fail("alpha must be a number or a percentage");
        const double a = c.kind == Component::Kind::Percent ? c.value / 100.0 : c.value;
        return round_byte(std::clamp(a, 0.0, 1.0) * 255.0);
    }

    Color parse_rgb(std::string_view args) {
        Component c[4];
        bool legacy = false;
        const int n = components("rgb", args, c, legacy);
        for (int i = 0; i < 3; ++i)
            if (c[i].kind == Component::Kind::Dimension)
                fail("rgb() components must be numbers or percentages, got unit '" + std::string(c[i].unit) + "'");
        if (legacy && !(c[0].kind == c[1].kind && c[1].kind == c[2].kind))
            fail("rgb() with commas needs all three components as numbers or all as percentages");
        std::uint8_t v[3];
        for (int i = 0; i < 3; ++i) {
            v[i] = c[i].kind == Component::Kind::Percent
                       ? round_byte(std::clamp(c[i].value, 0.0, 100.0) * 255.0 / 100.0)
                       : round_byte(std::clamp(c[i].value, 0.0, 255.0));
        }
        return {v[0], v[1], v[2], n == 4 ? alpha(c[3]) : std::uint8_t{255}};
    }

    Color parse_hsl(std::string_view args) {
        Component c[4];
        bool legacy = false;
        const int n = components("hsl", args, c, legacy);
        double hue = c[0].value;  // degrees
        if (c[0].kind == Component::Kind::Percent) fail("the hue of hsl() cannot be a percentage");
        if (c[0].kind == Component::Kind::Dimension) {
            const std::string_view u = c[0].unit;
            if (iequals(u, "deg")) {
            } else if (iequals(u, "rad")) {
                hue = hue * 180.0 / kPi;
            } else if (iequals(u, "grad")) {
                hue = hue * 0.9;
            } else if (iequals(u, "turn")) {
                hue = hue * 360.0;
            } else {
                fail("unknown hue unit '" + std::string(u) + "'; expected deg, rad, grad or turn");
            }
        }
        if (!std::isfinite(hue)) fail("the hue is out of range");
        hue = std::fmod(hue, 360.0);
        if (hue < 0) hue += 360.0;
        double sl[2];
        for (int i = 1; i <= 2; ++i) {
            const char* what = i == 1 ? "saturation" : "lightness";
            if (c[i].kind == Component::Kind::Dimension)
                fail(std::string("hsl() ") + what + " must be a percentage, got unit '" + std::string(c[i].unit) + "'");
            if (legacy && c[i].kind != Component::Kind::Percent)
                fail(std::string("hsl() with commas needs the ") + what + " as a percentage");
            sl[i - 1] = std::clamp(c[i].value, 0.0, 100.0) / 100.0;
        }
        // CSS Color 4, section 7.1 (hslToRgb): f(n) = L - a max(-1, min(k - 3, 9 - k, 1)),
        // k = (n + H/30) mod 12, a = S min(L, 1 - L); red, green, blue are f(0), f(8), f(4).
        const double s = sl[0], l = sl[1];
        const double a = s * std::min(l, 1.0 - l);
        auto f = [&](double k0) {
            const double k = std::fmod(k0 + hue / 30.0, 12.0);
            const double v = l - a * std::max(-1.0, std::min({k - 3.0, 9.0 - k, 1.0}));
            return round_byte(std::clamp(v, 0.0, 1.0) * 255.0);
        };
        return {f(0), f(8), f(4), n == 4 ? alpha(c[3]) : std::uint8_t{255}};
    }

    std::string_view full_;
    std::string_view args_;
    std::size_t pos_ = 0;
};

}  // namespace

Color parse_color(std::string_view text) { return Parser(text).parse(); }

}  // namespace casteljau
