// Curve toolkit: normals, projections, iso-parameter grids and shaded quads for surfaces
// (include/casteljau/surface.hpp, "projections and drawings").
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "casteljau/limits.hpp"
#include "casteljau/surface.hpp"
#include "curves/curve_util.hpp"

namespace casteljau {

using namespace curves_detail;

// ---- projections --------------------------------------------------------------------------------

namespace {
double oblique_factor(Projection kind) {
    switch (kind) {
        case Projection::Cavalier: return std::numbers::sqrt2 / 2;
        case Projection::Cabinet: return std::numbers::sqrt2 / 4;
        case Projection::Orthographic: return 0;
    }
    return 0;
}
}  // namespace

Point project(const Point3& p, Projection kind) {
    const double c = oblique_factor(kind);
    return {p.x - c * p.z, p.y - c * p.z};
}

Point3 View::rotate(const Point3& p) const {
    const double cy = std::cos(yaw), sy = std::sin(yaw), cp = std::cos(pitch), sp = std::sin(pitch);
    const double x = cy * p.x + sy * p.z, z = -sy * p.x + cy * p.z;
    return {x, cp * p.y - sp * z, sp * p.y + cp * z};
}

Point View::apply(const Point3& p) const {
    const Point q = project(rotate(p), projection);
    return {q.x * scale + offset.x, q.y * scale + offset.y};
}

double View::depth(const Point3& p) const {
    const double c = oblique_factor(projection);
    const Point3 d = Point3{c, c, 1} / std::sqrt(2 * c * c + 1);
    return rotate(p).dot(d);
}

// ---- normals ------------------------------------------------------------------------------------

namespace {

template <class S>
Point3 surface_normal(const S& s, double u, double v, double u0, double u1, double v0, double v1) {
    for (int attempt = 0; attempt < 2; ++attempt) {
        const Point3 n = s.du(u, v).cross(s.dv(u, v));
        const double len = n.length();
        if (len > 0 && std::isfinite(len)) return n / len;
        // Degenerate (a collapsed edge): step towards the centre of the domain.
        u += (0.5 * (u0 + u1) - u) * 1e-6;
        v += (0.5 * (v0 + v1) - v) * 1e-6;
    }
    return {};
}

struct Domain {
    double u0, u1, v0, v1;
};
Domain domain_of(const BezierPatch<Point3>&) { return {0, 1, 0, 1}; }
template <class S>
Domain domain_of(const S& s) {
    return {s.u_start(), s.u_end(), s.v_start(), s.v_end()};
}

}  // namespace

Point3 normal(const BezierPatch<Point3>& s, double u, double v) { return surface_normal(s, u, v, 0, 1, 0, 1); }
Point3 normal(const BSplineSurface<Point3>& s, double u, double v) {
    return surface_normal(s, u, v, s.u_start(), s.u_end(), s.v_start(), s.v_end());
}
Point3 normal(const NurbsSurface<Point3>& s, double u, double v) {
    return surface_normal(s, u, v, s.u_start(), s.u_end(), s.v_start(), s.v_end());
}

// ---- iso grids ----------------------------------------------------------------------------------

namespace {

void check_lines(int lines, const char* name) {
    if (lines == 0) return;
    if (lines < 2 || lines > limits::kMaxGridLines)
        throw Error(ErrorKind::InvalidArgument, std::string(name) + " must be 0 or 2 to " +
                                                    std::to_string(limits::kMaxGridLines) + ", got " +
                                                    std::to_string(lines));
}

double grid_param(double a, double b, int i, int lines) { return i == lines - 1 ? b : a + (b - a) * i / (lines - 1); }

void add_curve(Path& path, const Bezier<Point3>& c, const View& view, double tol) {
    std::vector<Point> pts;
    for (const Point3& p : c.points()) pts.push_back(view.apply(p));
    append_to_path(path, Bezier<Point>(std::move(pts)), tol);
}

void add_curve(Path& path, const BSpline<Point3>& c, const View& view, double tol) {
    for (const auto& piece : c.to_bezier()) add_curve(path, piece, view, tol);
}

void add_curve(Path& path, const Nurbs<Point3>& c, const View& view, double tol) {
    for (const auto& piece : c.to_bezier()) {
        std::vector<Point> pts;
        for (const Point3& p : piece.points()) pts.push_back(view.apply(p));
        append_to_path(
            path,
            RationalBezier<Point>(std::move(pts), std::vector<double>(piece.weights().begin(), piece.weights().end())),
            tol);
    }
}

template <class S>
Path grid(const S& s, const View& view, int lines_u, int lines_v, double tol) {
    check_lines(lines_u, "lines_u");
    check_lines(lines_v, "lines_v");
    const Domain d = domain_of(s);
    Path path;
    for (int i = 0; i < lines_u; ++i) {
        path.move_to(view.apply(s.eval(grid_param(d.u0, d.u1, i, lines_u), d.v0)));  // each line its own contour
        add_curve(path, s.iso_u(grid_param(d.u0, d.u1, i, lines_u)), view, tol);
    }
    for (int j = 0; j < lines_v; ++j) {
        path.move_to(view.apply(s.eval(d.u0, grid_param(d.v0, d.v1, j, lines_v))));
        add_curve(path, s.iso_v(grid_param(d.v0, d.v1, j, lines_v)), view, tol);
    }
    return path;
}

}  // namespace

Path iso_grid(const BezierPatch<Point3>& s, const View& view, int lines_u, int lines_v, double tolerance) {
    return grid(s, view, lines_u, lines_v, tolerance);
}
Path iso_grid(const BSplineSurface<Point3>& s, const View& view, int lines_u, int lines_v, double tolerance) {
    return grid(s, view, lines_u, lines_v, tolerance);
}
Path iso_grid(const NurbsSurface<Point3>& s, const View& view, int lines_u, int lines_v, double tolerance) {
    return grid(s, view, lines_u, lines_v, tolerance);
}

// ---- shaded quads -------------------------------------------------------------------------------

namespace {

template <class S>
std::vector<ShadedQuad> quads(const S& s, const View& view, int cu, int cv, Point3 light) {
    if (cu < 1 || cv < 1 || static_cast<std::size_t>(cu) * static_cast<std::size_t>(cv) > limits::kMaxShadedQuads)
        throw Error(ErrorKind::InvalidArgument, "shaded quads: cells must be >= 1 per direction and at most " +
                                                    std::to_string(limits::kMaxShadedQuads) + " in all");
    const double ll = light.length();
    if (!(ll > 0) || !std::isfinite(ll))
        throw Error(ErrorKind::InvalidArgument, "shaded quads: light must be a non-zero finite vector");
    const Point3 L = light / ll;
    const Domain d = domain_of(s);
    const auto CU = static_cast<std::size_t>(cu), CV = static_cast<std::size_t>(cv);
    std::vector<Point> corner((CU + 1) * (CV + 1));
    for (std::size_t i = 0; i <= CU; ++i)
        for (std::size_t j = 0; j <= CV; ++j)
            corner[i * (CV + 1) + j] = view.apply(s.eval(grid_param(d.u0, d.u1, static_cast<int>(i), cu + 1),
                                                         grid_param(d.v0, d.v1, static_cast<int>(j), cv + 1)));
    std::vector<ShadedQuad> out;
    out.reserve(CU * CV);
    // Rotating a normal: the rotation part of the view is linear, so rotate(n) - rotate(0) = rotate(n).
    for (std::size_t i = 0; i < CU; ++i) {
        for (std::size_t j = 0; j < CV; ++j) {
            const double uc = d.u0 + (d.u1 - d.u0) * (static_cast<double>(i) + 0.5) / cu;
            const double vc = d.v0 + (d.v1 - d.v0) * (static_cast<double>(j) + 0.5) / cv;
            ShadedQuad q;
            q.corners = {corner[i * (CV + 1) + j], corner[(i + 1) * (CV + 1) + j], corner[(i + 1) * (CV + 1) + j + 1],
                         corner[i * (CV + 1) + j + 1]};
            q.depth = view.depth(s.eval(uc, vc));
            const Point3 n = view.rotate(normal(s, uc, vc));
            q.shade = std::min(1.0, std::abs(n.dot(L)));
            out.push_back(q);
        }
    }
    std::stable_sort(out.begin(), out.end(),
                     [](const ShadedQuad& a, const ShadedQuad& b) { return a.depth > b.depth; });
    return out;
}

}  // namespace

std::vector<ShadedQuad> shaded_quads(const BezierPatch<Point3>& s, const View& view, int cells_u, int cells_v,
                                     Point3 light) {
    return quads(s, view, cells_u, cells_v, light);
}
std::vector<ShadedQuad> shaded_quads(const BSplineSurface<Point3>& s, const View& view, int cells_u, int cells_v,
                                     Point3 light) {
    return quads(s, view, cells_u, cells_v, light);
}
std::vector<ShadedQuad> shaded_quads(const NurbsSurface<Point3>& s, const View& view, int cells_u, int cells_v,
                                     Point3 light) {
    return quads(s, view, cells_u, cells_v, light);
}

}  // namespace casteljau
