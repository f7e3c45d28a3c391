// Filter stage: feMorphology. Erode (minimum) or dilate (maximum) of each premultiplied channel
// over a window of 2 rx x 2 ry pixels, columns x - rx .. x + rx - 1 and rows likewise (resvg's
// window, one pixel narrower than the symmetric 2 r + 1), separably, with pixels outside the
// region transparent.
// Each line uses the van Herk / Gil-Werman scheme (block prefix and suffix extrema), so the cost
// per pixel does not grow with the radius.
#include "filter/image.hpp"

namespace casteljau::filter::detail {

namespace {

// Replaces line[i] (n values, `stride` apart) by the extremum over [i - r, i + r - 1].
void extremum_line(float* line, std::size_t stride, int n, int r, bool dilate, std::vector<float>& ext,
                   std::vector<float>& g, std::vector<float>& h) {
    const int k = 2 * r;
    const int len = n + 2 * r - 1;
    const int blocks = (len + k - 1) / k;
    const std::size_t total = static_cast<std::size_t>(blocks) * static_cast<std::size_t>(k);
    ext.assign(total, 0.0f);
    for (int i = 0; i < n; ++i) ext[static_cast<std::size_t>(i + r)] = line[static_cast<std::size_t>(i) * stride];
    g.resize(total);
    h.resize(total);
    auto pick = [dilate](float a, float b) { return dilate ? std::max(a, b) : std::min(a, b); };
    for (std::size_t b0 = 0; b0 < total; b0 += static_cast<std::size_t>(k)) {
        g[b0] = ext[b0];
        for (std::size_t i = 1; i < static_cast<std::size_t>(k); ++i) g[b0 + i] = pick(g[b0 + i - 1], ext[b0 + i]);
        const std::size_t last = b0 + static_cast<std::size_t>(k) - 1;
        h[last] = ext[last];
        for (std::size_t i = last; i > b0; --i) h[i - 1] = pick(h[i], ext[i - 1]);
    }
    // Window [i, i + 2r - 1] of ext (line pixels i - r .. i + r - 1): h at its start, g at its end.
    for (int i = 0; i < n; ++i)
        line[static_cast<std::size_t>(i) * stride] =
            pick(h[static_cast<std::size_t>(i)], g[static_cast<std::size_t>(i + 2 * r - 1)]);
}

}  // namespace

Img morphology(const Img& in, int rx, int ry, bool dilate) {
    Img out = in;
    std::vector<float> ext, g, h;
    if (rx > 0)
        for (int y = 0; y < out.h; ++y)
            for (int c = 0; c < 4; ++c) extremum_line(out.at(0, y) + c, 4, out.w, rx, dilate, ext, g, h);
    if (ry > 0)
        for (int x = 0; x < out.w; ++x)
            for (int c = 0; c < 4; ++c)
                extremum_line(out.at(x, 0) + c, static_cast<std::size_t>(out.w) * 4, out.h, ry, dilate, ext, g, h);
    return out;
}

}  // namespace casteljau::filter::detail
