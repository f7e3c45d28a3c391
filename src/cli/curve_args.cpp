// Shared input/output helpers for the curve commands (see curve_args.hpp).
#include "cli/curve_args.hpp"

#include <simdjson.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "casteljau/error.hpp"
#include "cli/cli.hpp"

namespace casteljau::cli {

std::vector<Point> PointList::as_2d() const {
    std::vector<Point> out;
    out.reserve(points.size());
    for (const Point3& p : points) out.push_back({p.x, p.y});
    return out;
}

double PointList::scale() const {
    double s = 0;
    for (const Point3& p : points) s = std::max({s, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    return s;
}

namespace {

bool parse_double(const std::string& s, double& out) {
    if (s.empty()) return false;
    errno = 0;
    char* end = nullptr;
    out = std::strtod(s.c_str(), &end);
    return end == s.c_str() + s.size() && errno != ERANGE && std::isfinite(out);
}

std::vector<std::string> split(const std::string& text, const std::string& seps) {
    std::vector<std::string> parts;
    std::string cur;
    for (char c : text) {
        if (seps.find(c) != std::string::npos) {
            if (!cur.empty()) parts.push_back(cur);
            cur.clear();
        } else {
            cur += c;
        }
    }
    if (!cur.empty()) parts.push_back(cur);
    return parts;
}

}  // namespace

PointList parse_points_option(const std::string& option, const std::string& text) {
    PointList list;
    const auto tokens = split(text, " \t\n\r;");
    for (std::size_t k = 0; k < tokens.size(); ++k) {
        const auto coords = split(tokens[k], ",");
        // A token must be exactly "a,b" or "a,b,c" (no empty fields).
        const auto commas = static_cast<std::size_t>(std::count(tokens[k].begin(), tokens[k].end(), ','));
        if ((coords.size() != 2 && coords.size() != 3) || commas + 1 != coords.size())
            throw UsageError(option + ": point " + std::to_string(k + 1) + " '" + tokens[k] +
                             "' is not 'x,y' or 'x,y,z'");
        double v[3] = {0, 0, 0};
        for (std::size_t c = 0; c < coords.size(); ++c)
            if (!parse_double(coords[c], v[c]))
                throw UsageError(option + ": point " + std::to_string(k + 1) + " has a bad number '" + coords[c] + "'");
        const int dim = static_cast<int>(coords.size());
        if (k == 0)
            list.dimension = dim;
        else if (dim != list.dimension)
            throw UsageError(option + ": point " + std::to_string(k + 1) + " has " + std::to_string(dim) +
                             " coordinates but the first has " + std::to_string(list.dimension));
        list.points.push_back({v[0], v[1], v[2]});
    }
    return list;
}

std::vector<double> parse_numbers_option(const std::string& option, const std::string& text) {
    std::vector<double> out;
    for (const auto& tok : split(text, " \t\n\r,;")) {
        double v = 0;
        if (!parse_double(tok, v)) throw UsageError(option + ": '" + tok + "' is not a finite number");
        out.push_back(v);
    }
    return out;
}

namespace {

[[noreturn]] void bad_file(const std::string& path, const std::string& what) {
    throw Error(ErrorKind::Parse, path + ": " + what);
}

double number_of(const simdjson::dom::element& e, const std::string& path, const std::string& where) {
    double v = 0;
    if (e.get_double().get(v) != simdjson::SUCCESS || !std::isfinite(v)) bad_file(path, where + " is not a number");
    return v;
}

PointList points_of(const simdjson::dom::element& e, const std::string& path, const std::string& member) {
    simdjson::dom::array arr;
    if (e.get_array().get(arr) != simdjson::SUCCESS)
        bad_file(path, "\"" + member + "\" must be an array of [x, y] or [x, y, z]");
    PointList list;
    std::size_t k = 0;
    for (simdjson::dom::element pe : arr) {
        ++k;
        simdjson::dom::array pa;
        const std::string where = "\"" + member + "\"[" + std::to_string(k - 1) + "]";
        if (pe.get_array().get(pa) != simdjson::SUCCESS) bad_file(path, where + " must be an array of 2 or 3 numbers");
        std::vector<double> c;
        for (simdjson::dom::element ce : pa) c.push_back(number_of(ce, path, where));
        if (c.size() != 2 && c.size() != 3) bad_file(path, where + " must have 2 or 3 coordinates");
        const int dim = static_cast<int>(c.size());
        if (k == 1)
            list.dimension = dim;
        else if (dim != list.dimension)
            bad_file(path, where + " has a different dimension than the first point");
        list.points.push_back({c[0], c[1], c.size() == 3 ? c[2] : 0.0});
    }
    return list;
}

std::vector<double> numbers_of(const simdjson::dom::element& e, const std::string& path, const std::string& member) {
    simdjson::dom::array arr;
    if (e.get_array().get(arr) != simdjson::SUCCESS) bad_file(path, "\"" + member + "\" must be an array of numbers");
    std::vector<double> out;
    for (simdjson::dom::element x : arr) out.push_back(number_of(x, path, "\"" + member + "\" entry"));
    return out;
}

}  // namespace

CurveFile read_curve_file(const std::string& path) {
    const std::string text = read_text_input(path);
    simdjson::dom::parser parser;
    simdjson::dom::element doc;
    const simdjson::padded_string padded(text);
    if (const auto err = parser.parse(padded).get(doc); err != simdjson::SUCCESS)
        bad_file(path, std::string("invalid JSON: ") + simdjson::error_message(err));
    simdjson::dom::object obj;
    if (doc.get_object().get(obj) != simdjson::SUCCESS) bad_file(path, "the top level must be a JSON object");
    CurveFile f;
    simdjson::dom::element e;
    if (obj["points"].get(e) != simdjson::SUCCESS) bad_file(path, "missing \"points\"");
    f.points = points_of(e, path, "points");
    if (obj["tangents"].get(e) == simdjson::SUCCESS) f.tangents = points_of(e, path, "tangents");
    if (obj["weights"].get(e) == simdjson::SUCCESS) f.weights = numbers_of(e, path, "weights");
    if (obj["knots"].get(e) == simdjson::SUCCESS) f.knots = numbers_of(e, path, "knots");
    if (obj["degree"].get(e) == simdjson::SUCCESS) {
        int64_t d = 0;
        if (e.get_int64().get(d) != simdjson::SUCCESS || d < 0 || d > 1000000)
            bad_file(path, "\"degree\" must be a non-negative integer");
        f.degree = static_cast<int>(d);
    }
    return f;
}

std::string format_number(double v, double scale) {
    if (std::abs(v) <= 1e-12 * scale) v = 0;
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.12g", v);
    std::string s = buf;
    if (s == "-0") s = "0";
    return s;
}

std::string format_point(const Point& p, double scale) {
    return format_number(p.x, scale) + " " + format_number(p.y, scale);
}

std::string format_point(const Point3& p, double scale, int dimension) {
    std::string s = format_number(p.x, scale) + " " + format_number(p.y, scale);
    if (dimension == 3) s += " " + format_number(p.z, scale);
    return s;
}

}  // namespace casteljau::cli
