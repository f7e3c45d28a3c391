// Formats stage, SVG conversion: the geometry of the basic shapes (path, rect, circle, ellipse,
// line, polyline, polygon) and length attributes.
#include "formats/svg/context.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "casteljau/svg_path.hpp"

namespace casteljau::svg {

double length_attr(Context& cx, const pugi::xml_node& n, const char* name, double percent_of, double fallback) {
    const char* v = n.attribute(name).value();
    if (!*v) return fallback;
    auto l = parse_length(v, percent_of, font_size_of(cx, n), cx.options.dpi);
    if (!l) {
        warn(cx, std::string("invalid ") + name + " '" + v + "' on <" + n.name() + ">");
        return fallback;
    }
    return *l;
}

std::optional<Path> shape_path(Context& cx, const pugi::xml_node& n, Viewport vp) {
    const std::string_view name = n.name();
    const double diag = vp.diagonal();
    Path p;
    if (name == "path") {
        std::string err;
        p = parse_svg_path_lenient(n.attribute("d").value(), &err);
        if (!err.empty()) warn(cx, err);
    } else if (name == "rect") {
        const double x = length_attr(cx, n, "x", vp.w), y = length_attr(cx, n, "y", vp.h);
        const double w = length_attr(cx, n, "width", vp.w), h = length_attr(cx, n, "height", vp.h);
        if (!(w > 0) || !(h > 0)) return std::nullopt;
        double rx = length_attr(cx, n, "rx", vp.w, -1), ry = length_attr(cx, n, "ry", vp.h, -1);
        if (rx < 0 && ry < 0)
            rx = ry = 0;
        else if (rx < 0)
            rx = ry;
        else if (ry < 0)
            ry = rx;
        p.add_round_rect(Rect::from_xywh(x, y, w, h), std::min(rx, w / 2), std::min(ry, h / 2));
    } else if (name == "circle") {
        const double r = length_attr(cx, n, "r", diag);
        if (!(r > 0)) return std::nullopt;
        p.add_circle({length_attr(cx, n, "cx", vp.w), length_attr(cx, n, "cy", vp.h)}, r);
    } else if (name == "ellipse") {
        double rx = length_attr(cx, n, "rx", vp.w, -1), ry = length_attr(cx, n, "ry", vp.h, -1);
        if (rx < 0 && ry < 0) return std::nullopt;
        if (rx < 0) rx = ry;
        if (ry < 0) ry = rx;
        if (!(rx > 0) || !(ry > 0)) return std::nullopt;
        p.add_ellipse({length_attr(cx, n, "cx", vp.w), length_attr(cx, n, "cy", vp.h)}, rx, ry);
    } else if (name == "line") {
        p.move_to(length_attr(cx, n, "x1", vp.w), length_attr(cx, n, "y1", vp.h));
        p.line_to(length_attr(cx, n, "x2", vp.w), length_attr(cx, n, "y2", vp.h));
    } else if (name == "polyline" || name == "polygon") {
        std::string err;
        p = parse_points_lenient(n.attribute("points").value(), name == "polygon", &err);
        if (!err.empty()) warn(cx, "<" + std::string(name) + ">: " + err);
        if (p.points().size() < 2) return std::nullopt;
    } else {
        return std::nullopt;
    }
    return p;
}

}  // namespace casteljau::svg
