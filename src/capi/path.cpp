// C API: paths and stroke styles (casteljau.h).
#include "capi/handles.hpp"
#include "casteljau/svg_path.hpp"

using namespace casteljau;
using casteljau::capi::guard;
using casteljau::capi::need;

namespace {

void check_finite(std::initializer_list<double> values) {
    for (double v : values)
        if (!std::isfinite(v)) throw Error(ErrorKind::InvalidArgument, "a path coordinate is not finite");
}

template <class F>
casteljau_status edit(casteljau_path* path, F&& f) noexcept {
    return guard([&] { f(need(path, "path")->path); });
}

}  // namespace

extern "C" {

casteljau_path* casteljau_path_create(void) {
    casteljau_path* p = nullptr;
    return casteljau::capi::create(&p, [] { return Path{}; }) == CASTELJAU_OK ? p : nullptr;
}

void casteljau_path_destroy(casteljau_path* path) { delete path; }

casteljau_status casteljau_path_from_svg(const char* data, casteljau_path** out) {
    return casteljau::capi::create(out, [&] { return parse_svg_path(need(data, "data")); });
}

casteljau_status casteljau_path_move_to(casteljau_path* path, double x, double y) {
    return edit(path, [&](Path& p) {
        check_finite({x, y});
        p.move_to(x, y);
    });
}

casteljau_status casteljau_path_line_to(casteljau_path* path, double x, double y) {
    return edit(path, [&](Path& p) {
        check_finite({x, y});
        p.line_to(x, y);
    });
}

casteljau_status casteljau_path_quad_to(casteljau_path* path, double cx, double cy, double x, double y) {
    return edit(path, [&](Path& p) {
        check_finite({cx, cy, x, y});
        p.quad_to({cx, cy}, {x, y});
    });
}

casteljau_status casteljau_path_cubic_to(casteljau_path* path, double c1x, double c1y, double c2x, double c2y, double x,
                                         double y) {
    return edit(path, [&](Path& p) {
        check_finite({c1x, c1y, c2x, c2y, x, y});
        p.cubic_to({c1x, c1y}, {c2x, c2y}, {x, y});
    });
}

casteljau_status casteljau_path_close(casteljau_path* path) {
    return edit(path, [](Path& p) { p.close(); });
}

casteljau_status casteljau_path_add_rect(casteljau_path* path, double x, double y, double w, double h) {
    return edit(path, [&](Path& p) {
        check_finite({x, y, w, h});
        p.add_rect(Rect::from_xywh(x, y, w, h));
    });
}

casteljau_status casteljau_path_add_ellipse(casteljau_path* path, double cx, double cy, double rx, double ry) {
    return edit(path, [&](Path& p) {
        check_finite({cx, cy, rx, ry});
        p.add_ellipse({cx, cy}, rx, ry);
    });
}

casteljau_status casteljau_path_add_round_rect(casteljau_path* path, double x, double y, double w, double h, double rx,
                                               double ry) {
    return edit(path, [&](Path& p) {
        check_finite({x, y, w, h, rx, ry});
        p.add_round_rect(Rect::from_xywh(x, y, w, h), rx, ry);
    });
}

casteljau_status casteljau_path_transform(casteljau_path* path, const casteljau_matrix* m) {
    return edit(path, [&](Path& p) {
        const Affine a = casteljau::capi::affine(need(m, "matrix"));
        if (!a.is_finite()) throw Error(ErrorKind::InvalidArgument, "the matrix is not finite");
        p.transform(a);
    });
}

casteljau_status casteljau_path_bounds(const casteljau_path* path, double* x0, double* y0, double* x1, double* y1) {
    return guard([&] {
        const Path& p = need(path, "path")->path;
        const Rect b = p.empty() ? Rect{} : p.bounds();
        if (x0) *x0 = b.x0;
        if (y0) *y0 = b.y0;
        if (x1) *x1 = b.x1;
        if (y1) *y1 = b.y1;
    });
}

casteljau_stroke* casteljau_stroke_create(void) {
    casteljau_stroke* s = nullptr;
    return casteljau::capi::create(&s, [] { return StrokeStyle{}; }) == CASTELJAU_OK ? s : nullptr;
}

void casteljau_stroke_destroy(casteljau_stroke* stroke) { delete stroke; }

casteljau_status casteljau_stroke_set_width(casteljau_stroke* stroke, double width) {
    return guard([&] {
        if (!(width >= 0 && std::isfinite(width)))
            throw Error(ErrorKind::InvalidArgument, "stroke width must be finite and >= 0");
        need(stroke, "stroke")->style.width = width;
    });
}

casteljau_status casteljau_stroke_set_cap(casteljau_stroke* stroke, casteljau_line_cap line_cap) {
    return guard([&] {
        const int cap = casteljau::capi::raw_enum(line_cap);
        if (cap < CASTELJAU_CAP_BUTT || cap > CASTELJAU_CAP_SQUARE)
            throw Error(ErrorKind::InvalidArgument, "unknown line cap");
        need(stroke, "stroke")->style.cap = static_cast<LineCap>(cap);
    });
}

casteljau_status casteljau_stroke_set_join(casteljau_stroke* stroke, casteljau_line_join line_join,
                                           double miter_limit) {
    return guard([&] {
        const int join = casteljau::capi::raw_enum(line_join);
        if (join < CASTELJAU_JOIN_MITER || join > CASTELJAU_JOIN_BEVEL)
            throw Error(ErrorKind::InvalidArgument, "unknown line join");
        if (!std::isfinite(miter_limit)) throw Error(ErrorKind::InvalidArgument, "miter limit must be finite");
        StrokeStyle& s = need(stroke, "stroke")->style;
        s.join = static_cast<LineJoin>(join);
        s.miter_limit = miter_limit;
    });
}

casteljau_status casteljau_stroke_set_dashes(casteljau_stroke* stroke, const double* dashes, size_t count,
                                             double offset) {
    return guard([&] {
        StrokeStyle& s = need(stroke, "stroke")->style;
        if (count > 0) need(dashes, "dashes");
        if (count > 4096) throw Error(ErrorKind::Limit, "more than 4096 dash values");
        if (!std::isfinite(offset)) throw Error(ErrorKind::InvalidArgument, "dash offset must be finite");
        for (size_t i = 0; i < count; ++i)
            if (!std::isfinite(dashes[i])) throw Error(ErrorKind::InvalidArgument, "dash values must be finite");
        s.dashes.assign(dashes, dashes + count);
        s.dash_offset = offset;
    });
}

}  // extern "C"
