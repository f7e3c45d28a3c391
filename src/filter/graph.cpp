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
    detail::Context ctx;
    ctx.w = r.width();
    ctx.h = r.height();
    ctx.to_region = Affine::translate(-r.x0, -r.y0) * to_device;
    ctx.sx = std::hypot(to_device.a, to_device.b);
    ctx.sy = std::hypot(to_device.c, to_device.d);

    Img src(ctx.w, ctx.h, false);
    for (int y = 0; y < ctx.h; ++y) {
        const std::uint8_t* s = source.row(r.y0 + y) + 4 * static_cast<std::size_t>(r.x0);
        float* d = src.at(0, y);
        for (int i = 0; i < ctx.w * 4; ++i) d[i] = s[i] / 255.0f;
    }
    std::vector<Img> results;
    results.reserve(graph.primitives.size());
    for (std::size_t i = 0; i < graph.primitives.size(); ++i) {
        const Primitive& p = graph.primitives[i];
        auto input = [&](std::size_t k) {
            const Input in = k < p.inputs.size() ? p.inputs[k] : Input{};
            Img img;
            switch (in.kind) {
                case Input::Previous: img = results.empty() ? src : results.back(); break;
                case Input::SourceGraphic: img = src; break;
                case Input::SourceAlpha:
                    img = src;
                    for (std::size_t j = 0, n = img.count(); j < n; ++j)
                        img.px[j * 4] = img.px[j * 4 + 1] = img.px[j * 4 + 2] = 0;
                    break;
                case Input::Result:
                    if (in.index < 0 || static_cast<std::size_t>(in.index) >= results.size())
                        throw Error(ErrorKind::InvalidData, "filter primitive " + std::to_string(i) + " reads result " +
                                                                std::to_string(in.index) +
                                                                ", which is not an earlier one");
                    img = results[static_cast<std::size_t>(in.index)];
                    break;
            }
            detail::convert(img, p.linear_rgb);
            return img;
        };
        const IRect sub = device_rect(ctx.to_region, p.subregion, ctx.w, ctx.h);
        Img res;
        // The rectangle feTile repeats when it reads this result: its subregion, except that
        // feOffset passes on its input's (as resvg does), so an offset tile stays a tile.
        std::optional<IRect> tile_sub;
        switch (p.op) {
            case Primitive::Flood: res = flood(ctx.w, ctx.h, p.color, p.linear_rgb); break;
            case Primitive::Offset: {
                const Img in = input(0);
                res = detail::offset(in, p.dx * ctx.sx, p.dy * ctx.sy);
                tile_sub = in.sub;
                break;
            }
            case Primitive::Merge: {
                res = Img(ctx.w, ctx.h, p.linear_rgb);
                for (std::size_t k = 0; k < p.inputs.size(); ++k)
                    res = detail::composite(input(k), res, CompositeOp::Over, 0, 0, 0, 0);
                break;
            }
            case Primitive::Blend: res = detail::blend(input(0), input(1), p.blend); break;
            case Primitive::Composite:
                res = detail::composite(input(0), input(1), p.composite, p.k1, p.k2, p.k3, p.k4);
                break;
            case Primitive::GaussianBlur: {
                res = input(0);
                const double sx = p.std_x * ctx.sx, sy = p.std_y * ctx.sy;
                if (sx > 0 || sy > 0) detail::gaussian_blur(res, std::max(0.0, sx), std::max(0.0, sy), p.edge);
                break;
            }
            case Primitive::DropShadow: res = drop_shadow(input(0), ctx, p); break;
            case Primitive::ColorMatrix:
                res = input(0);
                detail::color_matrix(res, p.matrix);
                break;
            case Primitive::ComponentTransfer:
                res = input(0);
                detail::component_transfer(res, p.funcs);
                break;
            case Primitive::Morphology: {
                const double rx = std::min(std::round(p.rx * ctx.sx), static_cast<double>(ctx.w));
                const double ry = std::min(std::round(p.ry * ctx.sy), static_cast<double>(ctx.h));
                res = detail::morphology(input(0), static_cast<int>(std::max(0.0, rx)),
                                         static_cast<int>(std::max(0.0, ry)), p.dilate);
                break;
            }
            case Primitive::ConvolveMatrix: {
                if (p.order_x < 1 || p.order_y < 1 || p.order_x > limits::kMaxConvolveOrder ||
                    p.order_y > limits::kMaxConvolveOrder ||
                    p.kernel.size() != static_cast<std::size_t>(p.order_x) * static_cast<std::size_t>(p.order_y))
                    throw Error(ErrorKind::InvalidData,
                                "feConvolveMatrix kernel must be order x order values with order 1.." +
                                    std::to_string(limits::kMaxConvolveOrder));
                if (static_cast<long long>(p.order_x) * p.order_y * ctx.w * ctx.h > limits::kMaxConvolveWork)
                    throw Error(ErrorKind::Limit, "feConvolveMatrix of " + std::to_string(p.order_x) + " x " +
                                                      std::to_string(p.order_y) + " over " + std::to_string(ctx.w) +
                                                      " x " + std::to_string(ctx.h) + " pixels exceeds the limit of " +
                                                      std::to_string(limits::kMaxConvolveWork) + " kernel taps");
                res = detail::convolve(input(0), p);
                break;
            }
            case Primitive::Tile: {
                const Img in = input(0);
                res = detail::tile(in, in.sub);
                break;
            }
            case Primitive::Image: {
                Pixmap layer(source.width(), source.height());
                if (p.draw) p.draw(layer, to_device);
                res = Img(ctx.w, ctx.h, false);
                for (int y = 0; y < ctx.h; ++y) {
                    const std::uint8_t* s = layer.row(r.y0 + y) + 4 * static_cast<std::size_t>(r.x0);
                    float* d = res.at(0, y);
                    for (int k = 0; k < ctx.w * 4; ++k) d[k] = s[k] / 255.0f;
                }
                detail::convert(res, p.linear_rgb);
                break;
            }
            case Primitive::Turbulence: res = detail::turbulence(ctx, p, p.linear_rgb); break;
            case Primitive::DisplacementMap:
                res = detail::displacement(input(0), input(1), p.scale * ctx.sx, p.scale * ctx.sy, p.x_channel,
                                           p.y_channel);
                break;
            case Primitive::DiffuseLighting:
            case Primitive::SpecularLighting: res = detail::lighting(input(0), ctx, p, p.linear_rgb); break;
        }
        clear_outside(res, sub);
        if (tile_sub) res.sub = *tile_sub;
        results.push_back(std::move(res));
    }
    Img& last = results.back();
    detail::convert(last, false);
    for (int y = 0; y < ctx.h; ++y) {
        std::uint8_t* d = out.row(r.y0 + y) + 4 * static_cast<std::size_t>(r.x0);
        const float* s = last.at(0, y);
        for (int x = 0; x < ctx.w; ++x, s += 4, d += 4) {
            const float a = detail::clamp01(s[3]);
            d[3] = static_cast<std::uint8_t>(a * 255.0f + 0.5f);
            for (int k = 0; k < 3; ++k)
                d[k] = std::min(d[3], static_cast<std::uint8_t>(detail::clamp01(s[k]) * 255.0f + 0.5f));
        }
    }
    return out;
}

}  // namespace casteljau::filter
