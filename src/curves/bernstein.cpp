// Curve toolkit: the Bernstein basis, its power-form matrix and robust root isolation
// (include/casteljau/bezier.hpp).
#include <algorithm>
#include <cmath>
#include <vector>

#include "casteljau/bezier.hpp"
#include "curves/curve_util.hpp"
#include "casteljau/limits.hpp"

namespace casteljau {

using namespace curves_detail;

double binomial(int n, int k) {
    if (k < 0 || k > n || n < 0) return 0;
    k = std::min(k, n - k);
    // Multiplicative formula: after step i, r = C(n-k+i, i), an integer, and r * (n-k+i) is divisible
    // by i, so every step is exact while the values stay below 2^53.
    double r = 1;
    for (int i = 1; i <= k; ++i) r = r * (n - k + i) / i;
    return r;
}

double bernstein(int i, int n, double t) {
    if (n < 0 || i < 0 || i > n) return 0;
    return binomial(n, i) * std::pow(t, i) * std::pow(1 - t, n - i);
}

void bernstein_all(int n, double t, std::span<double> out) {
    if (n < 0 || out.size() != static_cast<std::size_t>(n) + 1)
        throw Error(ErrorKind::InvalidArgument, "bernstein_all: output size must be n + 1");
    // Triangle: B_{i,r} = (1-t) B_{i,r-1} + t B_{i-1,r-1}, built in place from the right.
    const double s = 1 - t;
    out[0] = 1;
    for (int r = 1; r <= n; ++r) {
        double saved = 0;
        for (int i = 0; i < r; ++i) {
            const double tmp = out[i];
            out[i] = saved + s * tmp;
            saved = t * tmp;
        }
        out[r] = saved;
    }
}

std::vector<double> bernstein_to_power_matrix(int n) {
    if (n < 0 || n > limits::kMaxBezierDegree)
        throw Error(ErrorKind::InvalidArgument, "bernstein_to_power_matrix: degree " + std::to_string(n) +
                                                    " is outside [0, " + std::to_string(limits::kMaxBezierDegree) +
                                                    "]");
    const std::size_t m = static_cast<std::size_t>(n) + 1;
    std::vector<double> M(m * m, 0.0);
    for (int k = 0; k <= n; ++k)
        for (int i = 0; i <= k; ++i)
            M[static_cast<std::size_t>(k) * m + static_cast<std::size_t>(i)] =
                ((k - i) % 2 ? -1.0 : 1.0) * binomial(n, k) * binomial(k, i);
    return M;
}

namespace {

// Sign changes among the non-zero coefficients (Descartes' rule for the Bernstein basis).
int sign_changes(const std::vector<double>& c) {
    int v = 0, last = 0;
    for (double x : c) {
        const int s = x > 0 ? 1 : x < 0 ? -1 : 0;
        if (s == 0) continue;
        if (last != 0 && s != last) ++v;
        last = s;
    }
    return v;
}

double eval_scalar(const std::vector<double>& c, double t, std::vector<double>& scratch) {
    scratch = c;
    return de_casteljau_inplace(scratch.data(), static_cast<int>(c.size()) - 1, t);
}

// Halves of c at 1/2 (de Casteljau's left and right edges).
void halve(const std::vector<double>& c, std::vector<double>& left, std::vector<double>& right) {
    const int n = static_cast<int>(c.size()) - 1;
    std::vector<double> b = c;
    left.assign(c.size(), 0);
    right.assign(c.size(), 0);
    left[0] = b[0];
    right[static_cast<std::size_t>(n)] = b[static_cast<std::size_t>(n)];
    for (int r = 1; r <= n; ++r) {
        for (int i = 0; i <= n - r; ++i)
            b[static_cast<std::size_t>(i)] =
                0.5 * (b[static_cast<std::size_t>(i)] + b[static_cast<std::size_t>(i) + 1]);
        left[static_cast<std::size_t>(r)] = b[0];
        right[static_cast<std::size_t>(n - r)] = b[static_cast<std::size_t>(n - r)];
    }
}

// The coefficients divided by their largest magnitude (checked: degree, finite values); empty when
// they are all (nearly) zero.
std::vector<double> normalized(std::span<const double> coeffs) {
    if (coeffs.size() > static_cast<std::size_t>(limits::kMaxBezierDegree) + 1)
        throw Error(ErrorKind::Limit, "bernstein_roots: degree " + std::to_string(coeffs.size() - 1) +
                                          " exceeds the limit of " + std::to_string(limits::kMaxBezierDegree));
    double scale = 0;
    for (double c : coeffs) {
        if (!std::isfinite(c)) throw Error(ErrorKind::InvalidData, "bernstein_roots: non-finite coefficient");
        scale = std::max(scale, std::abs(c));
    }
    if (scale <= 1e-300) return {};  // identically zero: no isolated roots
    std::vector<double> c(coeffs.begin(), coeffs.end());
    for (double& x : c) x /= scale;
    return c;
}

// The one simple root of c on [a, b] (its end values of opposite signs): bisection in the local
// parameter until the global interval cannot shrink any more.
double bisect_root(const std::vector<double>& c, double a, double b, std::vector<double>& scratch) {
    double lo = 0, hi = 1;
    const double sa = c.front();
    for (int k = 0; k < 64; ++k) {
        const double mid = 0.5 * (lo + hi);
        const double ga = a + (b - a) * lo, gb = a + (b - a) * hi;
        if (!(gb - ga > 2e-16 * std::max(1.0, std::abs(gb)))) break;
        const double fm = eval_scalar(c, mid, scratch);
        if (fm == 0) {
            lo = hi = mid;
            break;
        }
        if ((fm > 0) == (sa > 0))
            lo = mid;
        else
            hi = mid;
    }
    return a + (b - a) * 0.5 * (lo + hi);
}

// The roots sorted, clamped to [0, 1], those within 1e-14 of the previous one dropped.
std::vector<double> distinct_roots(std::vector<double> roots) {
    std::sort(roots.begin(), roots.end());
    std::vector<double> out;
    for (double r : roots) {
        r = std::clamp(r, 0.0, 1.0);
        if (out.empty() || r - out.back() > 1e-14) out.push_back(r);
    }
    return out;
}

}  // namespace

std::vector<double> bernstein_roots(std::span<const double> coeffs) {
    std::vector<double> roots;
    if (coeffs.size() < 2) return roots;
    std::vector<double> c0 = normalized(coeffs);
    if (c0.empty()) return roots;
    // Intervals of the parameter with the coefficients of the polynomial restricted to them, halved
    // until Descartes' rule of signs shows no root or exactly one simple root inside.
    struct Item {
        std::vector<double> c;
        double a, b;
        int depth;
    };
    std::vector<Item> stack;
    if (c0.back() == 0) roots.push_back(1.0);
    stack.push_back({std::move(c0), 0.0, 1.0, 0});
    std::vector<double> scratch, left, right;
    constexpr int kMaxDepth = 52;  // interval width 2^-52
    constexpr std::size_t kMaxWork =
        50000;  // intervals examined: a safety net (about 64 roots x 2 x 52 levels are needed at most)
    std::size_t work = 0;
    while (!stack.empty()) {
        Item it = std::move(stack.back());
        stack.pop_back();
        if (++work > kMaxWork) break;
        if (it.c.front() == 0) roots.push_back(it.a);
        const int v = sign_changes(it.c);
        if (v == 0) continue;
        if (v == 1 && it.c.front() != 0 && it.c.back() != 0) {
            roots.push_back(bisect_root(it.c, it.a, it.b, scratch));
            continue;
        }
        if (it.depth >= kMaxDepth) {
            roots.push_back(0.5 * (it.a + it.b));  // a cluster or multiple root
            continue;
        }
        halve(it.c, left, right);
        const double m = 0.5 * (it.a + it.b);
        stack.push_back({right, m, it.b, it.depth + 1});
        stack.push_back({left, it.a, m, it.depth + 1});
    }
    return distinct_roots(std::move(roots));
}

}  // namespace casteljau
