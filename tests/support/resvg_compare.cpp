// The resvg corpora's comparison and size rules (see resvg_compare.hpp).
#include "resvg_compare.hpp"
#include "skip.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <vector>

#include "casteljau/svg.hpp"

using casteljau::Pixmap;

namespace resvg_compare {

namespace {

int channel(const Pixmap& p, int x, int y, int c) { return p.row(y)[4 * x + c]; }

// True when pixel (x, y) of `a` lies outside [min - 24, max + 24] of b's 3x3 neighbourhood in
// some channel.
bool outside_neighbourhood(const Pixmap& a, const Pixmap& b, int x, int y) {
    for (int c = 0; c < 4; ++c) {
        int lo = 255, hi = 0;
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                const int xx = x + dx, yy = y + dy;
                if (xx < 0 || yy < 0 || xx >= b.width() || yy >= b.height()) continue;
                const int v = channel(b, xx, yy, c);
                lo = std::min(lo, v);
                hi = std::max(hi, v);
            }
        const int v = channel(a, x, y, c);
        if (v < lo - 24 || v > hi + 24) return true;
    }
    return false;
}

}  // namespace

Result compare(const Pixmap& actual, const Pixmap& reference) {
    Result r;
    if (actual.width() != reference.width() || actual.height() != reference.height()) return r;
    r.size_ok = true;
    const int w = actual.width(), h = actual.height();
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            int d = 0;
            for (int c = 0; c < 4; ++c)
                d = std::max(d, std::abs(channel(actual, x, y, c) - channel(reference, x, y, c)));
            if (d > 32) ++r.bad_a;
            if (d > 24 &&
                (outside_neighbourhood(actual, reference, x, y) || outside_neighbourhood(reference, actual, x, y)))
                ++r.bad_b;
        }
    const long long n = static_cast<long long>(w) * h;
    r.pass_a = static_cast<long long>(r.bad_a) * 200 <= n;
    r.pass_b = static_cast<long long>(r.bad_b) * 1000 <= n;
    return r;
}

Pixmap diff_image(const Pixmap& actual, const Pixmap& reference) {
    const int w = std::max(actual.width(), reference.width());
    const int h = std::max(actual.height(), reference.height());
    Pixmap out(3 * w, h);
    out.fill(casteljau::Color::white());
    auto blit = [&](const Pixmap& src, int ox) {
        for (int y = 0; y < src.height(); ++y)
            for (int x = 0; x < src.width(); ++x) {
                // Over white, so that transparent areas read as white.
                const casteljau::PremulPixel p = src.pixel(x, y);
                const int inv = 255 - p.a;
                out.set_pixel(ox + x, y,
                              {static_cast<std::uint8_t>(p.r + inv), static_cast<std::uint8_t>(p.g + inv),
                               static_cast<std::uint8_t>(p.b + inv), 255});
            }
    };
    blit(actual, 0);
    blit(reference, w);
    const bool same = actual.width() == reference.width() && actual.height() == reference.height();
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            std::uint8_t g = 255;
            if (x < reference.width() && y < reference.height())
                g = static_cast<std::uint8_t>(255 - reference.pixel(x, y).a / 4);
            casteljau::PremulPixel px{g, g, g, 255};
            if (!same) {
                px = {255, 0, 0, 255};
            } else {
                int d = 0;
                for (int c = 0; c < 4; ++c)
                    d = std::max(d, std::abs(channel(actual, x, y, c) - channel(reference, x, y, c)));
                if (d > 24 &&
                    (outside_neighbourhood(actual, reference, x, y) || outside_neighbourhood(reference, actual, x, y)))
                    px = {230, 0, 0, 255};
                else if (d > 32)
                    px = {255, 160, 0, 255};
            }
            out.set_pixel(2 * w + x, y, px);
        }
    return out;
}

Pixmap render_reference_size(const casteljau::SvgDocument& doc, bool native) {
    if (native) return doc.render();
    const auto [w, h] = doc.output_size_for_width(300);
    return doc.render_size(w, h);
}

std::filesystem::path shared_dir() { return casteljau::test::shared_dir(); }

}  // namespace resvg_compare
