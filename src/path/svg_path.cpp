// Path stage: SVG path data and points lists to Path, and Path to path data
// (include/casteljau/svg_path.hpp).
//
// The parser is a hand-written scanner over the bytes of the input: one pass, no allocation apart
// from the Path itself, no exceptions inside (errors are recorded with their byte position and turned
// into a message with a column at the end). Numbers are validated by the scanner against the SVG
// grammar and then converted by std::from_chars on exactly the validated token.
#include "casteljau/svg_path.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <limits>
#include <vector>

#include "casteljau/limits.hpp"
#include "path/arc_detail.hpp"

namespace casteljau {

namespace {

constexpr bool is_wsp(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f'; }
constexpr bool is_digit(char c) { return c >= '0' && c <= '9'; }
constexpr bool starts_number(char c) { return is_digit(c) || c == '-' || c == '+' || c == '.'; }

constexpr bool is_command(char c) {
    switch (c) {
        case 'M':
        case 'm':
        case 'L':
        case 'l':
        case 'H':
        case 'h':
        case 'V':
        case 'v':
        case 'C':
        case 'c':
        case 'S':
        case 's':
        case 'Q':
        case 'q':
        case 'T':
        case 't':
        case 'A':
        case 'a':
        case 'Z':
        case 'z': return true;
        default: return false;
    }
}

constexpr char to_upper(char c) { return (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c; }

// The reflection of p about `about`, used by S and T. The parser and the formatter share it, so the
// formatter can tell exactly when S / T reproduce a control point.
constexpr Point reflect(Point about, Point p) { return {2 * about.x - p.x, 2 * about.y - p.y}; }

// Bitwise equality of finite doubles (0 and -0 differ), so the formatter's shortcuts (H, V, S, T)
// never change a sign of zero.
bool same(double a, double b) { return a == b && std::signbit(a) == std::signbit(b); }
bool same(Point a, Point b) { return same(a.x, b.x) && same(a.y, b.y); }

// Names of the arguments of each command, for error messages.
struct CommandArgs {
    int count;
    const char* names[7];
};

CommandArgs command_args(char upper) {
    switch (upper) {
        case 'M':
        case 'L':
        case 'T': return {2, {"x", "y"}};
        case 'H': return {1, {"x"}};
        case 'V': return {1, {"y"}};
        case 'C': return {6, {"x1", "y1", "x2", "y2", "x", "y"}};
        case 'S': return {4, {"x2", "y2", "x", "y"}};
        case 'Q': return {4, {"x1", "y1", "x", "y"}};
        case 'A': return {7, {"rx", "ry", "x-axis-rotation", "large-arc-flag", "sweep-flag", "x", "y"}};
        default: return {0, {}};
    }
}

// Shared scanning: whitespace, separators, numbers, and error recording.
class Scanner {
public:
    Scanner(std::string_view s, const char* what) : s_(s), what_(what) {}

    bool at_end() const { return i_ >= s_.size(); }
    char peek() const { return s_[i_]; }

    void skip_wsp() {
        while (i_ < s_.size() && is_wsp(s_[i_])) ++i_;
    }
    // comma-wsp?: whitespace, at most one comma, whitespace.
    void skip_comma_wsp() {
        skip_wsp();
        if (i_ < s_.size() && s_[i_] == ',') {
            ++i_;
            skip_wsp();
        }
    }

    // The exponent part at s_[p] ('e' or 'E', sign?, digits): p moves past it and `exponent` gets
    // its value, saturated at 10^8. False (error recorded) when no digit follows.
    bool scan_exponent(std::size_t& p, long long& exponent) {
        const std::size_t n = s_.size();
        std::size_t q = p + 1;
        bool eneg = false;
        if (q < n && (s_[q] == '+' || s_[q] == '-')) {
            eneg = s_[q] == '-';
            ++q;
        }
        if (q >= n || !is_digit(s_[q])) {
            fail_at(q, std::string("a digit after '") + s_[q - 1] + "'");
            return false;
        }
        while (q < n && is_digit(s_[q])) {
            if (exponent < 100000000) exponent = exponent * 10 + (s_[q] - '0');
            ++q;
        }
        if (eneg) exponent = -exponent;
        p = q;
        return true;
    }

    // The decimal magnitude of a mantissa with integer digits s_[int_begin, int_end) and fraction
    // digits s_[frac_begin, frac_end): the position of its first nonzero digit relative to the
    // point (1 for 1.5, 0 for 0.5, -1 for 0.05). With the exponent, > 0 means |value| >= 1.
    long long decimal_magnitude(std::size_t int_begin, std::size_t int_end, std::size_t frac_begin,
                                std::size_t frac_end) const {
        std::size_t k = int_begin;
        while (k < int_end && s_[k] == '0') ++k;
        if (k < int_end) return static_cast<long long>(int_end - k);
        std::size_t z = frac_begin;
        while (z < frac_end && s_[z] == '0') ++z;
        return -static_cast<long long>(z - frac_begin);
    }

    enum class Num { Ok, None, Bad };

    // Scans one number at the current position: sign? (digits ('.' digits?)? | '.' digits)
    // (('e' | 'E') sign? digits)?. None: nothing number-like here (nothing consumed). Bad: a
    // malformed or overflowing number (error recorded).
    Num scan_number(double& out) {
        const std::size_t n = s_.size(), start = i_;
        std::size_t p = i_;
        bool neg = false;
        if (p < n && (s_[p] == '+' || s_[p] == '-')) {
            neg = s_[p] == '-';
            ++p;
        }
        const std::size_t int_begin = p;
        while (p < n && is_digit(s_[p])) ++p;
        const std::size_t int_end = p;
        std::size_t frac_begin = p, frac_end = p;
        if (p < n && s_[p] == '.') {
            frac_begin = ++p;
            while (p < n && is_digit(s_[p])) ++p;
            frac_end = p;
        }
        if (int_end == int_begin && frac_end == frac_begin) {
            if (p == start) return Num::None;
            fail_at(p, std::string("a digit after '") + s_[p - 1] + "'");
            return Num::Bad;
        }
        long long exponent = 0;  // saturated, only used to tell overflow from underflow
        if (p < n && (s_[p] == 'e' || s_[p] == 'E') && !scan_exponent(p, exponent)) return Num::Bad;
        // from_chars takes no '+'.
        const char* first = s_.data() + start + (s_[start] == '+' ? 1 : 0);
        double v = 0;
        const auto r = std::from_chars(first, s_.data() + p, v, std::chars_format::general);
        if (r.ec == std::errc::result_out_of_range) {
            if (decimal_magnitude(int_begin, int_end, frac_begin, frac_end) + exponent > 0) {
                fail_at(start, nullptr);
                error_ = "number out of range";
                return Num::Bad;
            }
            v = neg ? -0.0 : 0.0;
        } else if (r.ec != std::errc() || r.ptr != s_.data() + p || !std::isfinite(v)) {
            // Cannot happen for a token the scanner validated; kept as a guard.
            fail_at(start, "a number");
            return Num::Bad;
        }
        out = v;
        i_ = p;
        return Num::Ok;
    }

    // Records "expected <what>, found <thing at pos>" (what == nullptr: caller sets error_).
    bool fail_at(std::size_t pos, const std::string& what) { return fail_at(pos, what.c_str()); }
    bool fail_at(std::size_t pos, const char* what) {
        failed_ = true;
        error_pos_ = pos;
        if (what) error_ = std::string("expected ") + what + ", found " + describe(pos);
        return false;
    }

    bool failed() const { return failed_; }
    ErrorKind error_kind() const { return kind_; }
    void set_error_kind(ErrorKind k) { kind_ = k; }

    std::string message() const {
        return std::string(what_) + " column " + std::to_string(column(error_pos_)) + ": " + error_;
    }

protected:
    std::string_view s_;
    std::size_t i_ = 0;
    std::string error_;

private:
    // 1-based column in characters: UTF-8 continuation bytes do not count.
    std::size_t column(std::size_t pos) const {
        std::size_t col = 1;
        for (std::size_t k = 0; k < pos && k < s_.size(); ++k)
            if ((static_cast<unsigned char>(s_[k]) & 0xC0) != 0x80) ++col;
        return col;
    }

    std::string describe(std::size_t pos) const {
        if (pos >= s_.size()) return "end of data";
        const unsigned char c = static_cast<unsigned char>(s_[pos]);
        if (c >= 0x20 && c < 0x7f) return std::string("'") + static_cast<char>(c) + "'";
        char buf[32];
        // Decode one UTF-8 sequence for a readable U+XXXX; anything else is shown as a byte.
        std::uint32_t cp = 0;
        int len = 0;
        if (c < 0x80) {
            cp = c;
            len = 1;
        } else if ((c & 0xE0) == 0xC0) {
            cp = c & 0x1F;
            len = 2;
        } else if ((c & 0xF0) == 0xE0) {
            cp = c & 0x0F;
            len = 3;
        } else if ((c & 0xF8) == 0xF0) {
            cp = c & 0x07;
            len = 4;
        }
        bool ok = len > 0 && pos + static_cast<std::size_t>(len) <= s_.size();
        for (int k = 1; ok && k < len; ++k) {
            const unsigned char cc = static_cast<unsigned char>(s_[pos + static_cast<std::size_t>(k)]);
            if ((cc & 0xC0) != 0x80) ok = false;
            cp = (cp << 6) | (cc & 0x3F);
        }
        if (ok)
            std::snprintf(buf, sizeof buf, "U+%04X", static_cast<unsigned>(cp));
        else
            std::snprintf(buf, sizeof buf, "byte 0x%02X", static_cast<unsigned>(c));
        return buf;
    }

    const char* what_;
    bool failed_ = false;
    std::size_t error_pos_ = 0;
    ErrorKind kind_ = ErrorKind::Parse;
};

class PathDataParser : public Scanner {
public:
    PathDataParser(std::string_view d, const SvgPathOptions& options)
        : Scanner(d, "path data"),
          tolerance_(options.arc_tolerance),
          max_points_(std::min(options.max_points, current_limits().path_points)) {}

    // Parses everything; returns false at the first error (path() then holds the complete segments).
    bool parse() {
        skip_wsp();
        if (at_end()) return true;
        if (peek() != 'M' && peek() != 'm') return fail_at(i_, "'M' or 'm' at the start of path data");
        bool after_close = false;
        while (true) {
            skip_wsp();
            if (at_end()) return true;
            const char c = peek();
            if (!is_command(c))
                return fail_at(i_, after_close ? "a command letter after 'Z'" : "a number or a command letter");
            ++i_;
            if (c == 'Z' || c == 'z') {
                path_.close();
                prev_ = Prev::None;
                after_close = true;
                continue;
            }
            after_close = false;
            skip_wsp();
            if (!parse_command(c)) return false;
        }
    }

    Path& path() { return path_; }

private:
    enum class Prev { None, Cubic, Quad };

    bool parse_command(char cmd) {
        const char upper = to_upper(cmd);
        const CommandArgs args = command_args(upper);
        char effective = cmd;
        bool first_group = true;
        double a[7] = {};
        while (true) {
            const std::size_t group_pos = i_;
            for (int k = 0; k < args.count; ++k) {
                if (k > 0) skip_comma_wsp();
                if (upper == 'A' && (k == 3 || k == 4)) {
                    if (!at_end() && (peek() == '0' || peek() == '1')) {
                        a[k] = peek() == '1' ? 1 : 0;
                        ++i_;
                        continue;
                    }
                    return fail_at(i_, std::string("a flag (0 or 1) for ") + args.names[k] + " of '" + cmd + "'");
                }
                const Num r = scan_number(a[k]);
                if (r == Num::Bad) return false;
                if (r == Num::None) {
                    if (first_group && k == 0) return fail_at(i_, std::string("a number after '") + cmd + "'");
                    return fail_at(i_, std::string("a number for ") + args.names[k] + " of '" + cmd + "'");
                }
            }
            if (!apply(effective, a, group_pos)) return false;
            // Extra pairs after a moveto are implicit linetos.
            if (effective == 'M') effective = 'L';
            if (effective == 'm') effective = 'l';
            first_group = false;
            // Between argument groups: comma-wsp?, and the command repeats if a number follows.
            skip_wsp();
            if (!at_end() && peek() == ',') {
                ++i_;
                skip_wsp();
                if (at_end() || !starts_number(peek())) return fail_at(i_, "a number after ','");
                continue;
            }
            if (at_end() || !starts_number(peek())) return true;
        }
    }

    // Room for `added` more points (plus the move a segment after Z inserts)?
    bool reserve(std::size_t added, bool segment, std::size_t pos) {
        std::size_t need = added;
        if (segment && !path_.verbs().empty() && path_.verbs().back() == Verb::Close) ++need;
        if (path_.points().size() + need <= max_points_) return true;
        set_error_kind(ErrorKind::Limit);
        fail_at(pos, nullptr);
        error_ = "path data holds more than " + std::to_string(max_points_) + " points";
        return false;
    }

    bool out_of_range(std::size_t pos, const char* what = "number out of range") {
        fail_at(pos, nullptr);
        error_ = what;
        return false;
    }

    // Appends command `cmd` with its arguments `a` (read at `pos`); false with the error set.
    bool apply(char cmd, const double* a, std::size_t pos) {
        const bool rel = cmd >= 'a';
        switch (to_upper(cmd)) {
            case 'M': return apply_move(at(rel, a[0], a[1]), pos);
            case 'L': return apply_line(at(rel, a[0], a[1]), pos);
            case 'H': return apply_line({rel ? path_.current_point().x + a[0] : a[0], path_.current_point().y}, pos);
            case 'V': return apply_line({path_.current_point().x, rel ? path_.current_point().y + a[0] : a[0]}, pos);
            case 'C': return apply_cubic(at(rel, a[0], a[1]), at(rel, a[2], a[3]), at(rel, a[4], a[5]), pos);
            case 'S': return apply_cubic(smooth_control(Prev::Cubic), at(rel, a[0], a[1]), at(rel, a[2], a[3]), pos);
            case 'Q': return apply_quad(at(rel, a[0], a[1]), at(rel, a[2], a[3]), pos);
            case 'T': return apply_quad(smooth_control(Prev::Quad), at(rel, a[0], a[1]), pos);
            case 'A': return apply_arc(a, at(rel, a[5], a[6]), pos);
            default: return true;
        }
    }

    // (x, y), relative to the current point for a lower-case command.
    Point at(bool rel, double x, double y) const {
        const Point cur = path_.current_point();
        return rel ? Point{cur.x + x, cur.y + y} : Point{x, y};
    }

    // S and T: the previous control point reflected about the current point when the previous
    // command was of the same kind, else the current point.
    Point smooth_control(Prev kind) const {
        const Point cur = path_.current_point();
        return prev_ == kind ? reflect(cur, last_ctrl_) : cur;
    }

    bool apply_move(Point p, std::size_t pos) {
        if (!p.is_finite()) return out_of_range(pos);
        const bool merges = !path_.verbs().empty() && path_.verbs().back() == Verb::Move;
        if (!reserve(merges ? 0 : 1, false, pos)) return false;
        path_.move_to(p);
        prev_ = Prev::None;
        return true;
    }

    bool apply_line(Point p, std::size_t pos) {
        if (!p.is_finite()) return out_of_range(pos);
        if (!reserve(1, true, pos)) return false;
        path_.line_to(p);
        prev_ = Prev::None;
        return true;
    }

    bool apply_cubic(Point c1, Point c2, Point p, std::size_t pos) {
        if (!c1.is_finite() || !c2.is_finite() || !p.is_finite()) return out_of_range(pos);
        if (!reserve(3, true, pos)) return false;
        path_.cubic_to(c1, c2, p);
        prev_ = Prev::Cubic;
        last_ctrl_ = c2;
        return true;
    }

    bool apply_quad(Point c, Point p, std::size_t pos) {
        if (!c.is_finite() || !p.is_finite()) return out_of_range(pos);
        if (!reserve(2, true, pos)) return false;
        path_.quad_to(c, p);
        prev_ = Prev::Quad;
        last_ctrl_ = c;
        return true;
    }

    // An elliptical arc with radii a[0], a[1], rotation a[2] and flags a[3], a[4], ending at p: as
    // cubics, a line, or nothing (detail::arc_cubics).
    bool apply_arc(const double* a, Point p, std::size_t pos) {
        if (!p.is_finite()) return out_of_range(pos);
        if (arc_buf_.empty()) arc_buf_.resize(3 * limits::kMaxArcPieces);
        const detail::ArcCubics r =
            detail::arc_cubics(path_.current_point(), a[0], a[1], a[2], a[3] != 0, a[4] != 0, p, tolerance_, arc_buf_);
        prev_ = Prev::None;
        switch (r.kind) {
            case detail::ArcKind::Nothing: return true;
            case detail::ArcKind::Line:
                if (!reserve(1, true, pos)) return false;
                path_.line_to(p);
                return true;
            case detail::ArcKind::OutOfRange: return out_of_range(pos, "arc out of range");
            case detail::ArcKind::Cubics:
                if (!reserve(3 * static_cast<std::size_t>(r.count), true, pos)) return false;
                for (int i = 0; i < r.count; ++i) {
                    const Point* q = &arc_buf_[static_cast<std::size_t>(3 * i)];
                    path_.cubic_to(q[0], q[1], q[2]);
                }
                return true;
        }
        return true;
    }

    Path path_;
    Prev prev_ = Prev::None;
    Point last_ctrl_;
    double tolerance_;
    std::size_t max_points_;
    std::vector<Point> arc_buf_;
};

class PointsParser : public Scanner {
public:
    explicit PointsParser(std::string_view s) : Scanner(s, "points"), max_points_(current_limits().path_points) {}

    bool parse(bool close) {
        const bool ok = parse_points();
        if (close && !path_.empty()) path_.close();
        return ok;
    }

    Path& path() { return path_; }

private:
    bool parse_points() {
        skip_wsp();
        if (at_end()) return true;
        std::size_t count = 0;
        while (true) {
            double x = 0, y = 0;
            const std::size_t pos = i_;
            Num r = scan_number(x);
            if (r == Num::Bad) return false;
            if (r == Num::None) return fail_at(i_, "a number (x of point " + std::to_string(count + 1) + ")");
            skip_comma_wsp();
            r = scan_number(y);
            if (r == Num::Bad) return false;
            if (r == Num::None) return fail_at(i_, "a number (y of point " + std::to_string(count + 1) + ")");
            if (count >= max_points_) {
                set_error_kind(ErrorKind::Limit);
                fail_at(pos, nullptr);
                error_ = "more than " + std::to_string(max_points_) + " points";
                return false;
            }
            if (count == 0)
                path_.move_to({x, y});
            else
                path_.line_to({x, y});
            ++count;
            skip_wsp();
            if (!at_end() && peek() == ',') {
                ++i_;
                skip_wsp();
                if (at_end() || !starts_number(peek())) return fail_at(i_, "a number after ','");
                continue;
            }
            if (at_end()) return true;
            if (!starts_number(peek())) return fail_at(i_, "a number (x of point " + std::to_string(count + 1) + ")");
        }
    }

    Path path_;
    std::size_t max_points_;
};

void check_options(const SvgPathOptions& options) {
    if (!(options.arc_tolerance > 0))
        throw Error(ErrorKind::InvalidArgument, "SvgPathOptions::arc_tolerance must be a positive number");
}

// ---- Formatting ----

// Shortens a number written by to_chars: "0.5" -> ".5", "-0.5" -> "-.5", "1e+20" -> "1e20",
// "1e-05" -> "1e-5". Each form reads back to the same double.
std::size_t compact_number(char* b, std::size_t len) {
    std::size_t r = 0, w = 0;  // read and write positions; writing never overtakes reading
    if (len >= 3 && b[0] == '-' && b[1] == '0' && b[2] == '.') {
        b[w++] = '-';
        r = 2;
    } else if (len >= 2 && b[0] == '0' && b[1] == '.') {
        r = 1;
    }
    while (r < len && b[r] != 'e') b[w++] = b[r++];
    if (r < len) {
        b[w++] = b[r++];  // 'e'
        if (r < len && b[r] == '+')
            ++r;
        else if (r < len && b[r] == '-')
            b[w++] = b[r++];
        while (r + 1 < len && b[r] == '0') ++r;
        while (r < len) b[w++] = b[r++];
    }
    return w;
}

// Conics have no SVG form; they become cubics. For a conic piece (p0, p1, p2; w) the cubic with
// handles p0 + k (p1 - p0) and p2 + k (p1 - p2), k = 4w / (3 (1 + w)), shares its end points, end
// tangents and midpoint (for a circular arc it is the standard k = 4/3 tan(theta/4) cubic). Pieces are
// halved (exact rational subdivision) until the distance from 15 samples of the cubic to the conic is
// at most 0.8 x the tolerance (the margin covers the error between samples: the error curve is a
// smooth bump or two per piece). A quarter circle takes 8 cubics.
struct Conic {
    Point p0, p1, p2;
    double w;

    Point eval(double t) const {
        const double mt = 1 - t;
        const double b0 = mt * mt, b1 = 2 * w * mt * t, b2 = t * t;
        return (p0 * b0 + p1 * b1 + p2 * b2) / (b0 + b1 + b2);
    }
    Point derivative(double t) const {
        // C = N / D; C' = (N' D - N D') / D^2.
        const double mt = 1 - t;
        const Point n = p0 * (mt * mt) + p1 * (2 * w * mt * t) + p2 * (t * t);
        const double d = mt * mt + 2 * w * mt * t + t * t;
        const Point dn = p0 * (-2 * mt) + p1 * (2 * w * (1 - 2 * t)) + p2 * (2 * t);
        const double dd = -2 * mt + 2 * w * (1 - 2 * t) + 2 * t;
        return (dn * d - n * dd) / (d * d);
    }
    void split(Conic& left, Conic& right) const {
        const double s = 1 / (1 + w);
        const Point q01 = (p0 + p1 * w) * s, q12 = (p1 * w + p2) * s;
        const Point m = (p0 + p1 * (2 * w) + p2) * (0.5 * s);
        const double wm = std::sqrt((1 + w) / 2);
        left = {p0, q01, m, wm};
        right = {m, q12, p2, wm};
    }
};

Point eval_cubic(Point p0, Point p1, Point p2, Point p3, double t) {
    const double mt = 1 - t;
    return p0 * (mt * mt * mt) + p1 * (3 * mt * mt * t) + p2 * (3 * mt * t * t) + p3 * (t * t * t);
}

// Distance from q to the conic piece, starting the search at parameter t (Gauss-Newton on
// (C(s) - q) . C'(s) = 0, s kept in [0, 1]). Any s gives an upper bound of the distance.
double distance_to_conic(const Conic& c, Point q, double t) {
    double s = t;
    double best = distance(c.eval(s), q);
    for (int it = 0; it < 8; ++it) {
        const Point d = c.derivative(s);
        const double dd = d.dot(d);
        if (!(dd > 0)) break;
        s = std::clamp(s - (c.eval(s) - q).dot(d) / dd, 0.0, 1.0);
        best = std::min(best, distance(c.eval(s), q));
    }
    return best;
}

template <class Emit>
void conic_to_cubics(const Conic& c, double tolerance, int depth, Emit& emit) {
    const double k = 4 * c.w / (3 * (1 + c.w));
    const Point c1 = c.p0 + (c.p1 - c.p0) * k, c2 = c.p2 + (c.p1 - c.p2) * k;
    bool good = depth >= 12;
    if (!good) {
        double err = 0;
        for (int j = 1; j < 16 && err <= 0.8 * tolerance; ++j) {
            const double t = j / 16.0;
            err = std::max(err, distance_to_conic(c, eval_cubic(c.p0, c1, c2, c.p2, t), t));
        }
        good = err <= 0.8 * tolerance;
    }
    if (good) {
        emit(c1, c2, c.p2);
        return;
    }
    Conic l, r;
    c.split(l, r);
    conic_to_cubics(l, tolerance, depth + 1, emit);
    conic_to_cubics(r, tolerance, depth + 1, emit);
}

class Formatter {
public:
    explicit Formatter(std::string& out) : out_(out) {}

    void move(Point p) {
        command('M');
        number(p.x);
        number(p.y);
        last_cmd_ = 'L';  // further pairs after M would be linetos
        prev_ = Prev::None;
    }
    void line(Point a, Point b) {
        if (same(b.y, a.y)) {
            command('H');
            number(b.x);
        } else if (same(b.x, a.x)) {
            command('V');
            number(b.y);
        } else {
            command('L');
            number(b.x);
            number(b.y);
        }
        prev_ = Prev::None;
    }
    void quad(Point a, Point c, Point b) {
        if (same(c, prev_ == Prev::Quad ? reflect(a, last_ctrl_) : a)) {
            command('T');
        } else {
            command('Q');
            number(c.x);
            number(c.y);
        }
        number(b.x);
        number(b.y);
        prev_ = Prev::Quad;
        last_ctrl_ = c;
    }
    void cubic(Point a, Point c1, Point c2, Point b) {
        if (same(c1, prev_ == Prev::Cubic ? reflect(a, last_ctrl_) : a)) {
            command('S');
        } else {
            command('C');
            number(c1.x);
            number(c1.y);
        }
        number(c2.x);
        number(c2.y);
        number(b.x);
        number(b.y);
        prev_ = Prev::Cubic;
        last_ctrl_ = c2;
    }
    void conic(Point a, Point c, Point b, double w) {
        const Conic k{a, c, b, w};
        const double size = std::max({distance(a, c), distance(c, b), distance(a, b)});
        Point cur = a;
        auto emit = [&](Point c1, Point c2, Point p) {
            cubic(cur, c1, c2, p);
            cur = p;
        };
        conic_to_cubics(k, 1e-9 * size, 0, emit);
    }
    void close(Point, Point) {
        command('Z');
        prev_ = Prev::None;
    }

private:
    enum class Prev { None, Cubic, Quad };

    void command(char c) {
        if (c == last_cmd_ && c != 'M' && c != 'Z') return;  // implicit repetition
        out_ += c;
        last_cmd_ = c;
        have_number_ = false;
    }

    void number(double v) {
        char a[64], b[64];
        std::size_t la = 0, lb = 0;
        if (v == 0) {
            // "-0" keeps the sign: the round trip is exact to the bit.
            if (std::signbit(v)) a[la++] = '-';
            a[la++] = '0';
        } else {
            la = compact_number(a, static_cast<std::size_t>(std::to_chars(a, a + sizeof a, v).ptr - a));
            lb = compact_number(
                b, static_cast<std::size_t>(std::to_chars(b, b + sizeof b, v, std::chars_format::scientific).ptr - b));
        }
        const char* s = a;
        std::size_t len = la;
        if (lb > 0 && lb < la) {
            s = b;
            len = lb;
        }
        const std::string_view tok(s, len);
        if (have_number_ && !(tok[0] == '-' || (tok[0] == '.' && last_has_dot_))) out_ += ' ';
        out_.append(tok);
        have_number_ = true;
        last_has_dot_ = tok.find('.') != std::string_view::npos && tok.find('e') == std::string_view::npos;
    }

    std::string& out_;
    char last_cmd_ = 0;
    bool have_number_ = false;
    bool last_has_dot_ = false;
    Prev prev_ = Prev::None;
    Point last_ctrl_;
};

}  // namespace

Path parse_svg_path(std::string_view d, const SvgPathOptions& options) {
    check_options(options);
    PathDataParser p(d, options);
    if (!p.parse()) throw Error(p.error_kind(), p.message());
    return std::move(p.path());
}

Path parse_svg_path_lenient(std::string_view d, std::string* error, const SvgPathOptions& options) {
    check_options(options);
    PathDataParser p(d, options);
    const bool ok = p.parse();
    if (error) {
        if (ok)
            error->clear();
        else
            *error = p.message();
    }
    return std::move(p.path());
}

std::string format_svg_path(const Path& path) {
    if (!path.is_finite())
        throw Error(ErrorKind::InvalidArgument, "format_svg_path: the path has a non-finite coordinate");
    std::string out;
    out.reserve(path.verbs().size() * 12 + path.points().size() * 8);
    Formatter f(out);
    path.visit(f);
    return out;
}

Path parse_points(std::string_view points, bool close) {
    PointsParser p(points);
    if (!p.parse(close)) throw Error(p.error_kind(), p.message());
    return std::move(p.path());
}

Path parse_points_lenient(std::string_view points, bool close, std::string* error) {
    PointsParser p(points);
    const bool ok = p.parse(close);
    if (error) {
        if (ok)
            error->clear();
        else
            *error = p.message();
    }
    return std::move(p.path());
}

}  // namespace casteljau
