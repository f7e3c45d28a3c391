// Filter stage: the graph evaluator (include/casteljau/filter.hpp). Maps the filter region to
// device pixels (its bounding box, rounded out, clipped to the source), reads the source graphic
// into a float image, evaluates the primitives in order (each input converted to the primitive's
// colour space, each result made transparent outside its subregion) and writes the last result,
// back in sRGB, into a pixmap the size of the source.
#include <cmath>
#include <string>

#include "casteljau/error.hpp"
#include "casteljau/limits.hpp"
#include "filter/image.hpp"

namespace casteljau::filter {

namespace {

using detail::Img;

// The device pixels of user rectangle `r` under `m`, rounded out (with a small tolerance so
// that an edge landing on a pixel boundary up to rounding noise does not add a pixel), clipped
// to [0, w) x [0, h).
IRect device_rect(const Affine& m, const Rect& r, int w, int h) {
    const Rect b = transform_bounds(m, r);
    if (!std::isfinite(b.x0) || !std::isfinite(b.y0) || !std::isfinite(b.x1) || !std::isfinite(b.y1)) return {};
    auto lo = [](double v, int hi) {
        return static_cast<int>(std::clamp(std::floor(v + 1e-6), 0.0, static_cast<double>(hi)));
    };
    auto up = [](double v, int hi) {
        return static_cast<int>(std::clamp(std::ceil(v - 1e-6), 0.0, static_cast<double>(hi)));
    };
    IRect out{lo(b.x0, w), lo(b.y0, h), up(b.x1, w), up(b.y1, h)};
    if (out.empty()) return {};
    return out;
}

void clear_outside(Img& img, const IRect& sub) {
    for (int y = 0; y < img.h; ++y) {
        const bool row_in = y >= sub.y0 && y < sub.y1;
        for (int x = 0; x < img.w; ++x)
            if (!row_in || x < sub.x0 || x >= sub.x1) std::fill(img.at(x, y), img.at(x, y) + 4, 0.0f);
    }
    img.sub = sub;
}

Img flood(int w, int h, Color c, bool linear) {
    Img out(w, h, linear);
    const float a = c.a / 255.0f;
    float rgb[3] = {c.r / 255.0f, c.g / 255.0f, c.b / 255.0f};
    if (linear)
        for (float& v : rgb) v = detail::srgb_to_linear(v);
    float* p = out.px.data();
    for (std::size_t i = 0, n = out.count(); i < n; ++i, p += 4) {
        p[0] = rgb[0] * a;
        p[1] = rgb[1] * a;
        p[2] = rgb[2] * a;
        p[3] = a;
    }
    return out;
}

Img drop_shadow(const Img& in, const detail::Context& ctx, const Primitive& p) {
    Img shadow = flood(in.w, in.h, p.color, in.linear);
    for (std::size_t i = 0, n = in.count(); i < n; ++i)
        for (int k = 0; k < 4; ++k) shadow.px[i * 4 + static_cast<std::size_t>(k)] *= in.px[i * 4 + 3];
    detail::gaussian_blur(shadow, std::max(0.0, p.std_x * ctx.sx), std::max(0.0, p.std_y * ctx.sy), EdgeMode::None);
    shadow = detail::offset(shadow, p.dx * ctx.sx, p.dy * ctx.sy);
    return detail::composite(in, shadow, CompositeOp::Over, 0, 0, 0, 0);
}

}  // namespace

namespace {

// The pixels of `pm` in region r as a float image (premultiplied sRGB, 0..1).
Img read_region(const Pixmap& pm, const IRect& r) {
    Img img(r.width(), r.height(), false);
    for (int y = 0; y < img.h; ++y) {
        const std::uint8_t* s = pm.row(r.y0 + y) + 4 * static_cast<std::size_t>(r.x0);
        float* d = img.at(0, y);
        for (int i = 0; i < img.w * 4; ++i) d[i] = s[i] / 255.0f;
    }
    return img;
}

// Throws for a feConvolveMatrix whose kernel does not match its order or whose work passes the limit.
void check_convolve(const Primitive& p, const detail::Context& ctx) {
    if (p.order_x < 1 || p.order_y < 1 || p.order_x > limits::kMaxConvolveOrder ||
        p.order_y > limits::kMaxConvolveOrder ||
        p.kernel.size() != static_cast<std::size_t>(p.order_x) * static_cast<std::size_t>(p.order_y))
        throw Error(ErrorKind::InvalidData, "feConvolveMatrix kernel must be order x order values with order 1.." +
                                                std::to_string(limits::kMaxConvolveOrder));
    if (static_cast<long long>(p.order_x) * p.order_y * ctx.w * ctx.h > limits::kMaxConvolveWork)
        throw Error(ErrorKind::Limit, "feConvolveMatrix of " + std::to_string(p.order_x) + " x " +
                                          std::to_string(p.order_y) + " over " + std::to_string(ctx.w) + " x " +
                                          std::to_string(ctx.h) + " pixels exceeds the limit of " +
                                          std::to_string(limits::kMaxConvolveWork) + " kernel taps");
}

// One run of a filter graph over the device rectangle r of the source.
class FilterRun {
public:
    FilterRun(const FilterGraph& graph, const Affine& to_device, const Pixmap& source, const IRect& r)
        : graph_(graph), to_device_(to_device), source_(source), r_(r) {
        ctx_.w = r.width();
        ctx_.h = r.height();
        ctx_.to_region = Affine::translate(-r.x0, -r.y0) * to_device;
        ctx_.sx = std::hypot(to_device.a, to_device.b);
        ctx_.sy = std::hypot(to_device.c, to_device.d);
        src_ = read_region(source, r);
        results_.reserve(graph.primitives.size());
    }

    // Every primitive in order; the last one's result written into `out`'s region.
    void run(Pixmap& out) {
        for (std::size_t i = 0; i < graph_.primitives.size(); ++i) {
            const Primitive& p = graph_.primitives[i];
            // The rectangle feTile repeats when it reads this result: its subregion, except that
            // feOffset passes on its input's (as resvg does), so an offset tile stays a tile.
            std::optional<IRect> tile_sub;
            Img res = apply(p, i, tile_sub);
            clear_outside(res, device_rect(ctx_.to_region, p.subregion, ctx_.w, ctx_.h));
            if (tile_sub) res.sub = *tile_sub;
            results_.push_back(std::move(res));
        }
        write(results_.back(), out);
    }

private:
    // Input k of primitive p (the i-th), in p's colour space.
    Img input(const Primitive& p, std::size_t i, std::size_t k) const {
        const Input in = k < p.inputs.size() ? p.inputs[k] : Input{};
        Img img;
        switch (in.kind) {
            case Input::Previous: img = results_.empty() ? src_ : results_.back(); break;
            case Input::SourceGraphic: img = src_; break;
            case Input::SourceAlpha:
                img = src_;
                for (std::size_t j = 0, n = img.count(); j < n; ++j)
                    img.px[j * 4] = img.px[j * 4 + 1] = img.px[j * 4 + 2] = 0;
                break;
            case Input::Result:
                if (in.index < 0 || static_cast<std::size_t>(in.index) >= results_.size())
                    throw Error(ErrorKind::InvalidData, "filter primitive " + std::to_string(i) + " reads result " +
                                                            std::to_string(in.index) + ", which is not an earlier one");
                img = results_[static_cast<std::size_t>(in.index)];
                break;
        }
        detail::convert(img, p.linear_rgb);
        return img;
    }

    // The result of primitive p (the i-th), before its subregion is applied.
    Img apply(const Primitive& p, std::size_t i, std::optional<IRect>& tile_sub) const {
        auto in = [&](std::size_t k) { return input(p, i, k); };
        switch (p.op) {
            case Primitive::Flood: return flood(ctx_.w, ctx_.h, p.color, p.linear_rgb);
            case Primitive::Offset: {
                const Img a = in(0);
                tile_sub = a.sub;
                return detail::offset(a, p.dx * ctx_.sx, p.dy * ctx_.sy);
            }
            case Primitive::Merge: {
                Img res(ctx_.w, ctx_.h, p.linear_rgb);
                for (std::size_t k = 0; k < p.inputs.size(); ++k)
                    res = detail::composite(in(k), res, CompositeOp::Over, 0, 0, 0, 0);
                return res;
            }
            case Primitive::Blend: return detail::blend(in(0), in(1), p.blend);
            case Primitive::Composite: return detail::composite(in(0), in(1), p.composite, p.k1, p.k2, p.k3, p.k4);
            case Primitive::GaussianBlur: {
                Img res = in(0);
                const double sx = p.std_x * ctx_.sx, sy = p.std_y * ctx_.sy;
                if (sx > 0 || sy > 0) detail::gaussian_blur(res, std::max(0.0, sx), std::max(0.0, sy), p.edge);
                return res;
            }
            case Primitive::DropShadow: return drop_shadow(in(0), ctx_, p);
            case Primitive::ColorMatrix: {
                Img res = in(0);
                detail::color_matrix(res, p.matrix);
                return res;
            }
            case Primitive::ComponentTransfer: {
                Img res = in(0);
                detail::component_transfer(res, p.funcs);
                return res;
            }
            case Primitive::Morphology: {
                const double rx = std::min(std::round(p.rx * ctx_.sx), static_cast<double>(ctx_.w));
                const double ry = std::min(std::round(p.ry * ctx_.sy), static_cast<double>(ctx_.h));
                return detail::morphology(in(0), static_cast<int>(std::max(0.0, rx)),
                                          static_cast<int>(std::max(0.0, ry)), p.dilate);
            }
            case Primitive::ConvolveMatrix: check_convolve(p, ctx_); return detail::convolve(in(0), p);
            case Primitive::Tile: {
                const Img a = in(0);
                return detail::tile(a, a.sub);
            }
            case Primitive::Image: {
                Pixmap layer(source_.width(), source_.height());
                if (p.draw) p.draw(layer, to_device_);
                Img res = read_region(layer, r_);
                detail::convert(res, p.linear_rgb);
                return res;
            }
            case Primitive::Turbulence: return detail::turbulence(ctx_, p, p.linear_rgb);
            case Primitive::DisplacementMap:
                return detail::displacement(in(0), in(1), p.scale * ctx_.sx, p.scale * ctx_.sy, p.x_channel,
                                            p.y_channel);
            case Primitive::DiffuseLighting:
            case Primitive::SpecularLighting: return detail::lighting(in(0), ctx_, p, p.linear_rgb);
        }
        return Img{};
    }

    // The result, back in sRGB, into out's region as 8-bit premultiplied pixels.
    void write(Img& last, Pixmap& out) const {
        detail::convert(last, false);
        for (int y = 0; y < ctx_.h; ++y) {
            std::uint8_t* d = out.row(r_.y0 + y) + 4 * static_cast<std::size_t>(r_.x0);
            const float* s = last.at(0, y);
            for (int x = 0; x < ctx_.w; ++x, s += 4, d += 4) {
                const float a = detail::clamp01(s[3]);
                d[3] = static_cast<std::uint8_t>(a * 255.0f + 0.5f);
                for (int k = 0; k < 3; ++k)
                    d[k] = std::min(d[3], static_cast<std::uint8_t>(detail::clamp01(s[k]) * 255.0f + 0.5f));
            }
        }
    }

    const FilterGraph& graph_;
    const Affine& to_device_;
    const Pixmap& source_;
    const IRect r_;
    detail::Context ctx_;
    Img src_;
    std::vector<Img> results_;
};

}  // namespace

Pixmap apply_filter(const FilterGraph& graph, const Affine& to_device, const Pixmap& source) {
    const Limits lim = current_limits();
    if (graph.primitives.size() > lim.filter_primitives)
        throw Error(ErrorKind::Limit, "filter has " + std::to_string(graph.primitives.size()) + " primitives (limit " +
                                          std::to_string(lim.filter_primitives) + ")");
    Pixmap out(source.width(), source.height());
    const IRect r = device_rect(to_device, graph.region, source.width(), source.height());
    if (r.empty() || graph.primitives.empty()) return out;
    if (static_cast<long long>(r.width()) * r.height() > lim.filter_pixels)
        throw Error(ErrorKind::Limit, "filter region of " + std::to_string(r.width()) + " x " +
                                          std::to_string(r.height()) + " pixels exceeds the limit of " +
                                          std::to_string(lim.filter_pixels) + " pixels");
    FilterRun(graph, to_device, source, r).run(out);
    return out;
}

}  // namespace casteljau::filter
