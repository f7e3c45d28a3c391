// Formats stage: SVG filters (filter_graphs.hpp). The <filter> element and its href
// chain give the region (filterUnits), the primitive units and the primitives; each primitive's
// attributes become a filter::Primitive in the filtered element's user space. What the resvg
// test suite shows for invalid input is followed: a filter that names nothing, has no
// primitives, an empty region or bounding box with objectBoundingBox units, a subregion of zero
// or negative size or an unusable primitive hides the element; an `in` naming no earlier result
// reads the previous result (SourceGraphic for the first primitive); BackgroundImage,
// BackgroundAlpha, FillPaint and StrokePaint read SourceGraphic.
#include "formats/svg/filter_graphs.hpp"
#include "formats/svg/filter_values.hpp"
#include "formats/svg/references.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <map>

#include "casteljau/error.hpp"
#include "casteljau/limits.hpp"

namespace casteljau::svg_filter {

namespace {

double number_attr(const pugi::xml_node& n, const char* name, double fallback) {
    const pugi::xml_attribute a = n.attribute(name);
    if (!a) return fallback;
    auto v = number(a.value());
    return v ? *v : fallback;
}

// "a [b]": one or two numbers; nullopt when absent or malformed.
std::optional<std::pair<double, double>> number_pair(const pugi::xml_node& n, const char* name) {
    const pugi::xml_attribute a = n.attribute(name);
    if (!a) return std::nullopt;
    auto v = numbers(a.value());
    if (!v || v->empty() || v->size() > 2) return std::nullopt;
    return std::pair{(*v)[0], v->size() == 2 ? (*v)[1] : (*v)[0]};
}

Color flood_color(const pugi::xml_node& n, const SvgFilterEnv& env, const char* color_name, const char* opacity_name,
                  Color fallback) {
    Color c = fallback;
    std::string cv = env.property(n, color_name);
    // `inherit` (not an inherited property otherwise): the parent's value.
    if (cv.empty() && trim(n.attribute(color_name).value()) == "inherit") cv = env.property(n.parent(), color_name);
    if (!cv.empty()) {
        try {
            if (cv == "currentColor") {
                const std::string current = env.inherited(n, "color");
                c = current.empty() || current == "currentColor" ? env.current_color : env.color(current);
            } else {
                c = env.color(cv);
            }
        } catch (const Error&) {}
    }
    const std::string ov = env.property(n, opacity_name);
    if (!ov.empty()) {
        std::optional<double> o = fraction(ov);
        if (o) c = c.with_opacity(std::clamp(*o, 0.0, 1.0));
    }
    return c;
}

filter::EdgeMode edge_mode(const pugi::xml_node& n, filter::EdgeMode fallback) {
    const std::string_view v = trim(n.attribute("edgeMode").value());
    if (v == "none") return filter::EdgeMode::None;
    if (v == "duplicate") return filter::EdgeMode::Duplicate;
    if (v == "wrap") return filter::EdgeMode::Wrap;
    return fallback;
}

// Reads the primitive-specific attributes of `n` into `p`; false when the primitive is unusable.
// `len_x`/`len_y` scale lengths (the bounding box size with primitiveUnits objectBoundingBox, 1
// otherwise); `origin` is added to positions in objectBoundingBox units.
struct Units {
    bool bbox = false;
    Rect box;
    double x(double v) const { return bbox ? box.x0 + v * box.width() : v; }
    double y(double v) const { return bbox ? box.y0 + v * box.height() : v; }
    double lx(double v) const { return bbox ? v * box.width() : v; }
    double ly(double v) const { return bbox ? v * box.height() : v; }
    double lz(double v) const {
        return bbox ? v * std::sqrt((box.width() * box.width() + box.height() * box.height()) / 2) : v;
    }
};

bool read_light(const pugi::xml_node& n, const Units& u, filter::Light& l) {
    for (const pugi::xml_node& c : n.children()) {
        if (c.type() != pugi::node_element) continue;
        const std::string_view name = c.name();
        if (name == "feDistantLight") {
            l.type = filter::Light::Distant;
            l.azimuth = number_attr(c, "azimuth", 0);
            l.elevation = number_attr(c, "elevation", 0);
            return true;
        }
        if (name == "fePointLight" || name == "feSpotLight") {
            l.type = name == "fePointLight" ? filter::Light::Point : filter::Light::Spot;
            l.x = u.x(number_attr(c, "x", 0));
            l.y = u.y(number_attr(c, "y", 0));
            l.z = u.lz(number_attr(c, "z", 0));
            l.tx = u.x(number_attr(c, "pointsAtX", 0));
            l.ty = u.y(number_attr(c, "pointsAtY", 0));
            l.tz = u.lz(number_attr(c, "pointsAtZ", 0));
            // A negative exponent is 1, as Chrome (which pins it to [1, 128]) and resvg do.
            l.specular_exponent = number_attr(c, "specularExponent", 1);
            if (l.specular_exponent < 0) l.specular_exponent = 1;
            if (c.attribute("limitingConeAngle")) {
                auto a = number(c.attribute("limitingConeAngle").value());
                if (a) l.cone_angle = *a;
            }
            return true;
        }
    }
    return false;
}

// feColorMatrix: its type and values (an invalid list leaves the identity; an unknown type is
// the initial value, matrix).
void read_color_matrix(const pugi::xml_node& n, filter::Primitive& p) {
    using P = filter::Primitive;
    p.op = P::ColorMatrix;
    p.matrix = identity_matrix();
    const std::string_view type = trim(n.attribute("type").value());
    const pugi::xml_attribute values = n.attribute("values");
    auto v = numbers(values.value());
    if (type == "saturate") {
        if (values && v && v->size() == 1) p.matrix = saturate_matrix(std::max(0.0, (*v)[0]));
    } else if (type == "hueRotate") {
        if (values && v && v->size() == 1) p.matrix = hue_rotate_matrix((*v)[0]);
    } else if (type == "luminanceToAlpha") {
        p.matrix = luminance_to_alpha_matrix();
    } else {
        if (v && v->size() == 20) std::copy(v->begin(), v->end(), p.matrix.begin());
    }
}

// feComponentTransfer: one transfer function per feFuncR/G/B/A child.
void read_component_transfer(const pugi::xml_node& n, filter::Primitive& p) {
    using P = filter::Primitive;
    p.op = P::ComponentTransfer;
    for (const pugi::xml_node& f : n.children()) {
        const std::string_view fn = f.name();
        const int ch = fn == "feFuncR" ? 0 : fn == "feFuncG" ? 1 : fn == "feFuncB" ? 2 : fn == "feFuncA" ? 3 : -1;
        if (ch < 0) continue;
        filter::TransferFunction t;
        const std::string_view type = trim(f.attribute("type").value());
        if (type == "table" || type == "discrete") {
            auto tv = numbers(f.attribute("tableValues").value());
            if (tv && !tv->empty()) {
                t.type = type == "table" ? filter::TransferFunction::Table : filter::TransferFunction::Discrete;
                t.table = *tv;
            }
        } else if (type == "linear") {
            t.type = filter::TransferFunction::Linear;
            t.slope = number_attr(f, "slope", 1);
            t.intercept = number_attr(f, "intercept", 0);
        } else if (type == "gamma") {
            t.type = filter::TransferFunction::Gamma;
            t.amplitude = number_attr(f, "amplitude", 1);
            t.exponent = number_attr(f, "exponent", 1);
            t.offset = number_attr(f, "offset", 0);
        }
        p.funcs[static_cast<std::size_t>(ch)] = t;
    }
}

// feConvolveMatrix: order, kernel, divisor, bias, target, edge mode; false when invalid.
bool read_convolve_matrix(const pugi::xml_node& n, filter::Primitive& p) {
    using P = filter::Primitive;
    p.op = P::ConvolveMatrix;
    auto order =
        n.attribute("order") ? number_pair(n, "order") : std::optional<std::pair<double, double>>{std::pair{3.0, 3.0}};
    if (!order || order->first < 1 || order->second < 1 || order->first != std::floor(order->first) ||
        order->second != std::floor(order->second))
        return false;
    if (order->first > limits::kMaxConvolveOrder || order->second > limits::kMaxConvolveOrder)
        throw Error(ErrorKind::Limit, "feConvolveMatrix order " +
                                          std::to_string(static_cast<long long>(std::min(order->first, 1e18))) + " x " +
                                          std::to_string(static_cast<long long>(std::min(order->second, 1e18))) +
                                          " exceeds the limit of " + std::to_string(limits::kMaxConvolveOrder) + " x " +
                                          std::to_string(limits::kMaxConvolveOrder));
    p.order_x = static_cast<int>(order->first);
    p.order_y = static_cast<int>(order->second);
    auto k = numbers(n.attribute("kernelMatrix").value());
    if (!k || k->size() != static_cast<std::size_t>(p.order_x * p.order_y)) return false;
    p.kernel = *k;
    // The default divisor is the kernel's sum, 1 when that is zero. The values come from decimal
    // text, so a sum within the rounding of its terms (0.1 x 8 - 0.8 leaves -1e-16) is zero.
    double sum = 0, magnitude = 0;
    for (double v : p.kernel) {
        sum += v;
        magnitude += std::abs(v);
    }
    p.divisor = std::abs(sum) <= 1e-9 * magnitude ? 1 : sum;
    if (n.attribute("divisor")) {
        auto d = number(n.attribute("divisor").value());
        if (!d || *d == 0) return false;
        p.divisor = *d;
    }
    p.bias = number_attr(n, "bias", 0);
    p.target_x = p.order_x / 2;
    p.target_y = p.order_y / 2;
    if (n.attribute("targetX")) {
        auto t = number(n.attribute("targetX").value());
        if (!t || *t < 0 || *t >= p.order_x || *t != std::floor(*t)) return false;
        p.target_x = static_cast<int>(*t);
    }
    if (n.attribute("targetY")) {
        auto t = number(n.attribute("targetY").value());
        if (!t || *t < 0 || *t >= p.order_y || *t != std::floor(*t)) return false;
        p.target_y = static_cast<int>(*t);
    }
    p.edge = edge_mode(n, filter::EdgeMode::Duplicate);
    p.preserve_alpha = trim(n.attribute("preserveAlpha").value()) == "true";
    return true;
}

using P = filter::Primitive;

void read_composite(const pugi::xml_node& n, P& p) {
    p.op = P::Composite;
    const std::string_view o = trim(n.attribute("operator").value());
    using C = filter::CompositeOp;
    p.composite = o == "in"           ? C::In
                  : o == "out"        ? C::Out
                  : o == "atop"       ? C::Atop
                  : o == "xor"        ? C::Xor
                  : o == "arithmetic" ? C::Arithmetic
                  : o == "lighter"    ? C::Lighter
                                      : C::Over;
    p.k1 = number_attr(n, "k1", 0);
    p.k2 = number_attr(n, "k2", 0);
    p.k3 = number_attr(n, "k3", 0);
    p.k4 = number_attr(n, "k4", 0);
}

// feGaussianBlur and feDropShadow (a blur of the alpha, offset and flooded).
void read_blur(const pugi::xml_node& n, const Units& u, const SvgFilterEnv& env, bool shadow, P& p) {
    p.op = shadow ? P::DropShadow : P::GaussianBlur;
    auto sd = number_pair(n, "stdDeviation");
    double sx = shadow ? 2 : 0, sy = sx;
    if (sd) {
        sx = sd->first;
        sy = sd->second;
    }
    if (sx < 0 || sy < 0) sx = sy = 0;  // a negative deviation disables the blur
    p.std_x = u.lx(sx);
    p.std_y = u.ly(sy);
    p.edge = edge_mode(n, filter::EdgeMode::None);
    if (shadow) {
        p.dx = u.lx(number_attr(n, "dx", 2));
        p.dy = u.ly(number_attr(n, "dy", 2));
        p.color = flood_color(n, env, "flood-color", "flood-opacity", Color::black());
    }
}

void read_morphology(const pugi::xml_node& n, const Units& u, P& p) {
    p.op = P::Morphology;
    p.dilate = trim(n.attribute("operator").value()) == "dilate";
    // A missing, malformed or negative radius, or zero on both axes, is 1 (as resvg does); zero on
    // one axis only is 1 on that axis (as Chrome and Safari do).
    auto r = number_pair(n, "radius");
    if (!r || r->first < 0 || r->second < 0 || (r->first == 0 && r->second == 0)) r = std::pair{1.0, 1.0};
    if (r->first == 0) r->first = 1;
    if (r->second == 0) r->second = 1;
    p.rx = u.lx(r->first);
    p.ry = u.ly(r->second);
}

void read_turbulence(const pugi::xml_node& n, P& p) {
    p.op = P::Turbulence;
    auto f = n.attribute("baseFrequency") ? number_pair(n, "baseFrequency")
                                          : std::optional<std::pair<double, double>>{std::pair{0.0, 0.0}};
    if (!f || f->first < 0 || f->second < 0) f = std::pair{0.0, 0.0};
    p.freq_x = f->first;
    p.freq_y = f->second;
    const double oct = number_attr(n, "numOctaves", 1);
    p.octaves = oct < 0 ? 0 : static_cast<int>(std::min(oct, 64.0));
    p.seed = number_attr(n, "seed", 0);
    p.stitch = trim(n.attribute("stitchTiles").value()) == "stitch";
    p.fractal = trim(n.attribute("type").value()) == "fractalNoise";
}

void read_displacement(const pugi::xml_node& n, const Units& u, P& p) {
    p.op = P::DisplacementMap;
    p.scale = number_attr(n, "scale", 0);
    if (u.bbox) p.scale *= std::sqrt(u.box.width() * u.box.height());
    auto channel = [&](const char* a) {
        const std::string_view v = trim(n.attribute(a).value());
        return v == "R" ? 0 : v == "G" ? 1 : v == "B" ? 2 : 3;
    };
    p.x_channel = channel("xChannelSelector");
    p.y_channel = channel("yChannelSelector");
}

// feDiffuseLighting and feSpecularLighting; false for a specular exponent outside [1, 128] or a
// missing or invalid light source.
bool read_lighting(const pugi::xml_node& n, const Units& u, const SvgFilterEnv& env, bool specular, P& p) {
    p.op = specular ? P::SpecularLighting : P::DiffuseLighting;
    p.surface_scale = number_attr(n, "surfaceScale", 1);
    p.diffuse_constant = number_attr(n, "diffuseConstant", 1);
    p.specular_constant = number_attr(n, "specularConstant", 1);
    p.specular_exponent = number_attr(n, "specularExponent", 1);
    if (specular && !(p.specular_exponent >= 1 && p.specular_exponent <= 128)) return false;
    p.color = flood_color(n, env, "lighting-color", "lighting-opacity", Color::white());
    return read_light(n, u, p.light);
}

// The filter primitive element `n` read into `p`; false when it is unknown or invalid.
bool read_primitive(const pugi::xml_node& n, const Units& u, const SvgFilterEnv& env, P& p) {
    const std::string_view name = n.name();
    if (name == "feFlood") {
        p.op = P::Flood;
        p.color = flood_color(n, env, "flood-color", "flood-opacity", Color::black());
    } else if (name == "feOffset") {
        p.op = P::Offset;
        p.dx = u.lx(number_attr(n, "dx", 0));
        p.dy = u.ly(number_attr(n, "dy", 0));
    } else if (name == "feMerge" || name == "feTile") {
        p.op = name == "feMerge" ? P::Merge : P::Tile;
    } else if (name == "feBlend") {
        p.op = P::Blend;
        const std::string mode = std::string(trim(n.attribute("mode").value()));
        if (!mode.empty() && !parse_blend_mode(mode, p.blend)) p.blend = BlendMode::Normal;
    } else if (name == "feComposite") {
        read_composite(n, p);
    } else if (name == "feGaussianBlur" || name == "feDropShadow") {
        read_blur(n, u, env, name == "feDropShadow", p);
    } else if (name == "feColorMatrix") {
        read_color_matrix(n, p);
    } else if (name == "feComponentTransfer") {
        read_component_transfer(n, p);
    } else if (name == "feMorphology") {
        read_morphology(n, u, p);
    } else if (name == "feConvolveMatrix") {
        return read_convolve_matrix(n, p);
    } else if (name == "feImage") {
        p.op = P::Image;
        p.draw = env.image(n, p.subregion);
    } else if (name == "feTurbulence") {
        read_turbulence(n, p);
    } else if (name == "feDisplacementMap") {
        read_displacement(n, u, p);
    } else if (name == "feDiffuseLighting" || name == "feSpecularLighting") {
        return read_lighting(n, u, env, name == "feSpecularLighting", p);
    } else {
        return false;
    }
    return true;
}

}  // namespace

std::optional<filter::FilterGraph> build_filter(const pugi::xml_node& f, const std::optional<Rect>& bbox,
                                                const SvgFilterEnv& env) {
    const std::vector<pugi::xml_node> chain = svg::href_chain(f, env.lookup, {"filter"});
    auto attr = [&](const char* name) -> const char* {
        for (const pugi::xml_node& n : chain)
            if (const pugi::xml_attribute a = n.attribute(name)) return a.value();
        return nullptr;
    };
    pugi::xml_node content;
    for (const pugi::xml_node& n : chain)
        if (n.find_child([](const pugi::xml_node& c) { return c.type() == pugi::node_element; })) {
            content = n;
            break;
        }
    const char* fu = attr("filterUnits");
    const bool bbox_units = !(fu && trim(fu) == "userSpaceOnUse");
    const char* pu = attr("primitiveUnits");
    const bool prim_bbox = pu && trim(pu) == "objectBoundingBox";
    const bool have_box = bbox && bbox->width() > 0 && bbox->height() > 0;
    if ((bbox_units || prim_bbox) && !have_box) return std::nullopt;

    filter::FilterGraph g;
    auto region_value = [&](const char* name, double def_fraction, double size, double origin,
                            bool is_pos) -> std::optional<double> {
        const char* v = attr(name);
        if (bbox_units) {
            std::optional<double> fr = v ? fraction(v) : std::optional<double>(def_fraction);
            if (!fr) fr = def_fraction;
            return (is_pos ? origin : 0) + *fr * size;
        }
        const double vsize =
            (std::string_view(name) == "x" || std::string_view(name) == "width") ? env.viewport.w : env.viewport.h;
        std::optional<double> l = v ? env.length(v, vsize) : std::nullopt;
        if (!l) l = def_fraction * vsize;
        return l;
    };
    const Rect b = have_box ? *bbox : Rect{};
    const double rx = *region_value("x", -0.1, b.width(), b.x0, true),
                 ry = *region_value("y", -0.1, b.height(), b.y0, true);
    const double rw = *region_value("width", 1.2, b.width(), 0, false),
                 rh = *region_value("height", 1.2, b.height(), 0, false);
    if (!(rw > 0) || !(rh > 0)) return std::nullopt;
    g.region = Rect::from_xywh(rx, ry, rw, rh);

    Units u;
    u.bbox = prim_bbox;
    u.box = b;
    std::map<std::string, int, std::less<>> results;
    if (!content) return std::nullopt;
    for (const pugi::xml_node& n : content.children()) {
        if (n.type() != pugi::node_element) continue;
        const std::string_view name = n.name();
        if (name.substr(0, 2) != "fe") continue;
        filter::Primitive p;
        p.linear_rgb = env.inherited(n, "color-interpolation-filters") != "sRGB";
        // Subregion: x, y, width, height default to the filter region.
        const Rect base = g.region;
        auto sub = [&](const char* a, double def, bool horizontal, bool is_pos) -> std::optional<double> {
            const pugi::xml_attribute at = n.attribute(a);
            if (!at) return def;
            if (prim_bbox) {
                auto fr = fraction(at.value());
                if (!fr) return def;
                return horizontal ? (is_pos ? u.x(*fr) : u.lx(*fr)) : (is_pos ? u.y(*fr) : u.ly(*fr));
            }
            auto l = env.length(at.value(), horizontal ? env.viewport.w : env.viewport.h);
            return l ? *l : def;
        };
        const double sx = *sub("x", base.x0, true, true), sy = *sub("y", base.y0, false, true);
        const double sw = *sub("width", base.width(), true, false), sh = *sub("height", base.height(), false, false);
        if (!(sw > 0) || !(sh > 0)) return std::nullopt;
        p.subregion = Rect::from_xywh(sx, sy, sw, sh);
        // An `in` value: a standard input, an earlier result, or (empty or unknown) the previous.
        auto input = [&](const pugi::xml_node& node, const char* a) {
            const std::string_view v = trim(node.attribute(a).value());
            if (v == "SourceGraphic" || v == "BackgroundImage" || v == "BackgroundAlpha" || v == "FillPaint" ||
                v == "StrokePaint")
                return filter::Input::source_graphic();
            if (v == "SourceAlpha") return filter::Input::source_alpha();
            const auto it = results.find(v);
            if (!v.empty() && it != results.end()) return filter::Input::result(it->second);
            return filter::Input{};
        };
        if (!read_primitive(n, u, env, p)) return std::nullopt;
        if (p.op == filter::Primitive::Merge) {
            for (const pugi::xml_node& m : n.children("feMergeNode")) p.inputs.push_back(input(m, "in"));
        } else {
            p.inputs = {input(n, "in"), input(n, "in2")};
        }
        if (const std::size_t max_primitives = current_limits().filter_primitives;
            g.primitives.size() >= max_primitives)
            throw Error(ErrorKind::Limit, "filter has more than " + std::to_string(max_primitives) + " primitives");
        if (const char* r = n.attribute("result").value(); *r) results[r] = static_cast<int>(g.primitives.size());
        g.primitives.push_back(std::move(p));
    }
    if (g.primitives.empty()) return std::nullopt;
    return g;
}

}  // namespace casteljau::svg_filter
