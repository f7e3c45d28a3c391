// casteljau/surface.hpp: tensor-product surfaces (Bézier patches of any m x n degree, B-spline and
// NURBS surfaces), their derivatives and normals, and the projections and drawings that turn them
// into 2-D Paths: iso-parameter curve grids and shaded quads sorted back to front.
//
//   P(u, v) = sum_i sum_j P_ij B_(i,m)(u) B_(j,n)(v),  (u, v) in [0, 1]^2.
//
// Conventions: a control net is stored row-major with i (the u direction) as the row:
// net[i * (n + 1) + j] = P_ij for a Bézier patch (net[i * count_v + j] for spline surfaces).
// Evaluation is de Casteljau in u then v: each column j (fixed j, i = 0..m) is reduced at u to Q_j,
// then Q_0..Q_n at v. Partial derivatives use forward differences in each direction; the twist is
// P_uv. Normals are the unit P_u x P_v (3-D only).
// Projections map 3-D to 2-D: z is the receding axis (larger z is farther from the viewer).
// Oblique cavalier: x' = x - z sqrt(2)/2, y' = y - z sqrt(2)/2 (full depth); cabinet: half depth,
// x' = x - z sqrt(2)/4, y' = y - z sqrt(2)/4; orthographic: x' = x, y' = y. A View first rotates
// (yaw about the y axis, then pitch about the x axis), projects, then scales and offsets into the
// drawing's space. Every View is affine, so an iso curve's projection is the Bézier of its projected
// control points: grids are exact (degree <= 3) or within the proven tolerance (higher degrees).
// Limits: degrees 1..64 in each direction, at most limits::kMaxSurfacePoints control points,
// grids of at most limits::kMaxGridLines lines and limits::kMaxShadedQuads quads.
// Errors: as bezier.hpp / spline.hpp / nurbs.hpp, plus Error(InvalidData) for a net whose size does
// not match its degrees or counts.
// Thread-safety: immutable values; concurrent const use is safe. No global state.
#pragma once

#include <array>
#include <span>
#include <vector>

#include "casteljau/bezier.hpp"
#include "casteljau/limits.hpp"
#include "casteljau/nurbs.hpp"
#include "casteljau/path.hpp"
#include "casteljau/spline.hpp"
#include "casteljau/vec.hpp"

namespace casteljau {

// ---- Bézier patches -----------------------------------------------------------------------------

template <CurvePoint P>
class BezierPatch {
public:
    using point_type = P;

    // net.size() must be (degree_u + 1) (degree_v + 1), row i = u index.
    BezierPatch(int degree_u, int degree_v, std::vector<P> net);

    int degree_u() const { return m_; }
    int degree_v() const { return n_; }
    std::span<const P> net() const { return net_; }
    const P& at(int i, int j) const {
        return net_[static_cast<std::size_t>(i) * static_cast<std::size_t>(n_ + 1) + static_cast<std::size_t>(j)];
    }

    // De Casteljau in u then v. No allocation.
    P eval(double u, double v) const;
    P operator()(double u, double v) const { return eval(u, v); }
    // Bicubic only (else Error(InvalidArgument)): U M P M^T V^T with U = [u^3 u^2 u 1],
    // V = [v^3 v^2 v 1], M = [-1 3 -3 1; 3 -6 3 0; -3 3 0 0; 1 0 0 0].
    P eval_matrix(double u, double v) const;
    // d^(ku+kv) P / du^ku dv^kv (zero when ku > m or kv > n).
    P derivative(int ku, int kv, double u, double v) const;
    P du(double u, double v) const { return derivative(1, 0, u, v); }
    P dv(double u, double v) const { return derivative(0, 1, u, v); }
    P twist(double u, double v) const { return derivative(1, 1, u, v); }
    // The iso-parameter curves: v -> P(u, v) at fixed u (degree n) and u -> P(u, v) at fixed v (degree m).
    Bezier<P> iso_u(double u) const;
    Bezier<P> iso_v(double v) const;
    Box<P> control_bounds() const;

private:
    int m_ = 0, n_ = 0;
    std::vector<P> net_;
};

// The textbook bicubic Bézier matrix M (row-major, descending powers), as used by eval_matrix.
std::array<double, 16> bezier_cubic_matrix();

// ---- spline surfaces ----------------------------------------------------------------------------

template <CurvePoint P>
class BSplineSurface {
public:
    using point_type = P;

    // count_u x count_v control net (row i = u index), knots_u.size() = count_u + degree_u + 1, ...
    BSplineSurface(int degree_u, int degree_v, std::size_t count_u, std::size_t count_v, std::vector<P> net,
                   std::vector<double> knots_u, std::vector<double> knots_v);
    // Clamped (open uniform on [0, 1]) knots in both directions.
    static BSplineSurface clamped(int degree_u, int degree_v, std::size_t count_u, std::size_t count_v,
                                  std::vector<P> net);

    int degree_u() const { return pu_; }
    int degree_v() const { return pv_; }
    std::size_t count_u() const { return nu_; }
    std::size_t count_v() const { return nv_; }
    std::span<const P> net() const { return net_; }
    std::span<const double> knots_u() const { return ku_; }
    std::span<const double> knots_v() const { return kv_; }
    double u_start() const { return ku_[static_cast<std::size_t>(pu_)]; }
    double u_end() const { return ku_[nu_]; }
    double v_start() const { return kv_[static_cast<std::size_t>(pv_)]; }
    double v_end() const { return kv_[nv_]; }

    P eval(double u, double v) const { return derivative(0, 0, u, v); }
    P derivative(int ku, int kv, double u, double v) const;
    P du(double u, double v) const { return derivative(1, 0, u, v); }
    P dv(double u, double v) const { return derivative(0, 1, u, v); }
    P twist(double u, double v) const { return derivative(1, 1, u, v); }
    BSpline<P> iso_u(double u) const;  // v -> S(u, v)
    BSpline<P> iso_v(double v) const;  // u -> S(u, v)

private:
    int pu_ = 0, pv_ = 0;
    std::size_t nu_ = 0, nv_ = 0;
    std::vector<P> net_;
    std::vector<double> ku_, kv_;
};

template <CurvePoint P>
class NurbsSurface {
public:
    using point_type = P;

    NurbsSurface(int degree_u, int degree_v, std::size_t count_u, std::size_t count_v, std::vector<P> net,
                 std::vector<double> weights, std::vector<double> knots_u, std::vector<double> knots_v);

    int degree_u() const { return pu_; }
    int degree_v() const { return pv_; }
    std::size_t count_u() const { return nu_; }
    std::size_t count_v() const { return nv_; }
    std::span<const P> net() const { return net_; }
    std::span<const double> weights() const { return w_; }
    double u_start() const { return ku_[static_cast<std::size_t>(pu_)]; }
    double u_end() const { return ku_[nu_]; }
    double v_start() const { return kv_[static_cast<std::size_t>(pv_)]; }
    double v_end() const { return kv_[nv_]; }

    P eval(double u, double v) const { return derivative(0, 0, u, v); }
    // ku, kv in {0, 1} (quotient rule on the homogeneous surface); Error(InvalidArgument) otherwise.
    P derivative(int ku, int kv, double u, double v) const;
    P du(double u, double v) const { return derivative(1, 0, u, v); }
    P dv(double u, double v) const { return derivative(0, 1, u, v); }
    P twist(double u, double v) const { return derivative(1, 1, u, v); }
    Nurbs<P> iso_u(double u) const;
    Nurbs<P> iso_v(double v) const;

private:
    int pu_ = 0, pv_ = 0;
    std::size_t nu_ = 0, nv_ = 0;
    std::vector<P> net_;
    std::vector<double> w_, ku_, kv_;
};

// Unit normal P_u x P_v / |P_u x P_v|. At a degenerate point (a collapsed edge, P_u x P_v = 0) the
// normal is taken at a point moved 1e-6 of the domain towards its centre; the zero vector if that
// is degenerate too.
Point3 normal(const BezierPatch<Point3>& s, double u, double v);
Point3 normal(const BSplineSurface<Point3>& s, double u, double v);
Point3 normal(const NurbsSurface<Point3>& s, double u, double v);

// ---- projections and drawings -------------------------------------------------------------------

enum class Projection { Cavalier, Cabinet, Orthographic };

// The bare projections of the header comment.
Point project(const Point3& p, Projection kind);

struct View {
    Projection projection = Projection::Cavalier;
    double yaw = 0;    // radians, rotation about the y axis, applied first
    double pitch = 0;  // radians, rotation about the x axis, applied second
    double scale = 1;  // then x' = scale * px + offset.x, y' = scale * py + offset.y
    Point offset{};

    Point3 rotate(const Point3& p) const;
    Point apply(const Point3& p) const;
    // Distance along the viewing direction after rotation (larger is farther): the rotated point
    // dotted with the unit vector that the projection collapses, (c, c, 1) / |(c, c, 1)|.
    double depth(const Point3& p) const;
};

// `lines_u` iso-u curves at u = start + (end - start) i / (lines_u - 1) and `lines_v` iso-v curves,
// projected by `view`, one open contour each (lines >= 2 per direction, or 0 to omit a direction).
Path iso_grid(const BezierPatch<Point3>& s, const View& view, int lines_u, int lines_v, double tolerance = 0.01);
Path iso_grid(const BSplineSurface<Point3>& s, const View& view, int lines_u, int lines_v, double tolerance = 0.01);
Path iso_grid(const NurbsSurface<Point3>& s, const View& view, int lines_u, int lines_v, double tolerance = 0.01);

struct ShadedQuad {
    std::array<Point, 4> corners;  // projected (u0,v0), (u1,v0), (u1,v1), (u0,v1)
    double depth = 0;              // View::depth of the quad's centre (larger is farther)
    double shade = 0;              // Lambert |N . L| at the centre, in [0, 1]
};

// The surface sampled on cells_u x cells_v quads, each lit by a directional light `light` (any
// non-zero vector, pointing from the surface towards the light, in the rotated view frame;
// two-sided), sorted back to front (largest depth first) for the painter's algorithm.
std::vector<ShadedQuad> shaded_quads(const BezierPatch<Point3>& s, const View& view, int cells_u, int cells_v,
                                     Point3 light = {-0.4, -0.6, -1});
std::vector<ShadedQuad> shaded_quads(const BSplineSurface<Point3>& s, const View& view, int cells_u, int cells_v,
                                     Point3 light = {-0.4, -0.6, -1});
std::vector<ShadedQuad> shaded_quads(const NurbsSurface<Point3>& s, const View& view, int cells_u, int cells_v,
                                     Point3 light = {-0.4, -0.6, -1});

extern template class BezierPatch<Point>;
extern template class BezierPatch<Point3>;
extern template class BSplineSurface<Point>;
extern template class BSplineSurface<Point3>;
extern template class NurbsSurface<Point>;
extern template class NurbsSurface<Point3>;

}  // namespace casteljau
