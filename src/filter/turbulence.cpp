// Filter stage: feTurbulence, the Perlin noise of the SVG specification's reference
// implementation (its lattice, gradient tables and Park-Miller random numbers, stitching and
// fractal sum), written anew. Each pixel samples the noise at its top-left corner mapped back to
// user space; channel values are straight colour in the primitive's colour space.
#include <cmath>

#include "filter/image.hpp"

namespace casteljau::filter::detail {

namespace {

constexpr int kB = 0x100;
constexpr int kMask = 0xff;
constexpr int kPerlinN = 0x1000;
constexpr long kRandM = 2147483647, kRandA = 16807, kRandQ = 127773, kRandR = 2836;
constexpr int kMaxOctaves =
    10;  // octave k adds at most 2^-k: the ones after the tenth move no 8-bit value by more than 1/2

struct Noise {
    int lattice[kB + kB + 2];
    double gradient[4][kB + kB + 2][2];

    static long random(long seed) {
        long r = kRandA * (seed % kRandQ) - kRandR * (seed / kRandQ);
        if (r <= 0) r += kRandM;
        return r;
    }

    explicit Noise(long seed) {
        if (seed <= 0) seed = -(seed % (kRandM - 1)) + 1;
        if (seed > kRandM - 1) seed = kRandM - 1;
        int i = 0;
        for (int k = 0; k < 4; ++k) {
            for (i = 0; i < kB; ++i) {
                lattice[i] = i;
                for (int j = 0; j < 2; ++j) {
                    seed = random(seed);
                    gradient[k][i][j] = static_cast<double>((seed % (kB + kB)) - kB) / kB;
                }
                const double s =
                    std::sqrt(gradient[k][i][0] * gradient[k][i][0] + gradient[k][i][1] * gradient[k][i][1]);
                if (s > 0) {
                    gradient[k][i][0] /= s;
                    gradient[k][i][1] /= s;
                }
            }
        }
        while (--i) {
            const int k = lattice[i];
            seed = random(seed);
            const int j = static_cast<int>(seed % kB);
            lattice[i] = lattice[j];
            lattice[j] = k;
        }
        for (i = 0; i < kB + 2; ++i) {
            lattice[kB + i] = lattice[i];
            for (int k = 0; k < 4; ++k)
                for (int j = 0; j < 2; ++j) gradient[k][kB + i][j] = gradient[k][i][j];
        }
    }

    struct Stitch {
        int width, height, wrap_x, wrap_y;
    };

    double noise2(int channel, double vx, double vy, const Stitch* st) const {
        auto curve = [](double t) { return t * t * (3. - 2. * t); };
        auto lerp = [](double t, double a, double b) { return a + t * (b - a); };
        double t = vx + kPerlinN;
        int bx0 = static_cast<int>(t) & kMask, bx1 = (bx0 + 1) & kMask;
        const double rx0 = t - static_cast<int>(t), rx1 = rx0 - 1.0;
        t = vy + kPerlinN;
        int by0 = static_cast<int>(t) & kMask, by1 = (by0 + 1) & kMask;
        const double ry0 = t - static_cast<int>(t), ry1 = ry0 - 1.0;
        if (st) {
            if (bx0 >= st->wrap_x) bx0 -= st->width;
            if (bx1 >= st->wrap_x) bx1 -= st->width;
            if (by0 >= st->wrap_y) by0 -= st->height;
            if (by1 >= st->wrap_y) by1 -= st->height;
        }
        bx0 &= kMask;
        bx1 &= kMask;
        by0 &= kMask;
        by1 &= kMask;
        const int i = lattice[bx0], j = lattice[bx1];
        const int b00 = lattice[i + by0], b10 = lattice[j + by0], b01 = lattice[i + by1], b11 = lattice[j + by1];
        const double sx = curve(rx0), sy = curve(ry0);
        const double* q = gradient[channel][b00];
        double u = rx0 * q[0] + ry0 * q[1];
        q = gradient[channel][b10];
        double v = rx1 * q[0] + ry0 * q[1];
        const double a = lerp(sx, u, v);
        q = gradient[channel][b01];
        u = rx0 * q[0] + ry1 * q[1];
        q = gradient[channel][b11];
        v = rx1 * q[0] + ry1 * q[1];
        const double b = lerp(sx, u, v);
        return lerp(sy, a, b);
    }
};

}  // namespace

Img turbulence(const Context& ctx, const Primitive& p, bool linear) {
    Img out(ctx.w, ctx.h, linear);
    const auto inv = ctx.to_region.inverse();
    if (!inv || !(p.freq_x >= 0) || !(p.freq_y >= 0)) return out;
    const double seed_d = std::clamp(std::trunc(p.seed), -2147483647.0, 2147483647.0);
    const Noise noise(static_cast<long>(seed_d));
    double fx = p.freq_x, fy = p.freq_y;
    Noise::Stitch stitch{};
    const Rect& tile = p.subregion;
    if (p.stitch) {
        auto adjust = [](double f, double size) {
            if (f == 0 || !(size > 0)) return f;
            const double lo = std::floor(size * f) / size, hi = std::ceil(size * f) / size;
            return (lo > 0 && f / lo < hi / f) ? lo : hi;
        };
        fx = adjust(fx, tile.width());
        fy = adjust(fy, tile.height());
        stitch.width = static_cast<int>(tile.width() * fx + 0.5);
        stitch.wrap_x = static_cast<int>(tile.x0 * fx + kPerlinN + stitch.width);
        stitch.height = static_cast<int>(tile.height() * fy + 0.5);
        stitch.wrap_y = static_cast<int>(tile.y0 * fy + kPerlinN + stitch.height);
    }
    const int octaves = std::clamp(p.octaves, 0, kMaxOctaves);
    for (int y = 0; y < ctx.h; ++y) {
        for (int x = 0; x < ctx.w; ++x) {
            const Point u = inv->apply(Point{static_cast<double>(x), static_cast<double>(y)});
            float c[4];
            for (int ch = 0; ch < 4; ++ch) {
                Noise::Stitch st = stitch;
                double vx = u.x * fx, vy = u.y * fy, ratio = 1, sum = 0;
                for (int o = 0; o < octaves; ++o) {
                    const double n = noise.noise2(ch, vx, vy, p.stitch ? &st : nullptr);
                    sum += (p.fractal ? n : std::fabs(n)) / ratio;
                    vx *= 2;
                    vy *= 2;
                    ratio *= 2;
                    if (p.stitch) {
                        st.width *= 2;
                        st.wrap_x = 2 * st.wrap_x - kPerlinN;
                        st.height *= 2;
                        st.wrap_y = 2 * st.wrap_y - kPerlinN;
                    }
                }
                c[ch] = clamp01(static_cast<float>(p.fractal ? (sum + 1) / 2 : sum));
            }
            float* o = out.at(x, y);
            for (int k = 0; k < 3; ++k) o[k] = c[k] * c[3];
            o[3] = c[3];
        }
    }
    return out;
}

}  // namespace casteljau::filter::detail
