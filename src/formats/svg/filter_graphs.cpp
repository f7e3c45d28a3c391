// Formats stage: SVG filters (filter_graphs.hpp). The <filter> element and its href
// chain give the region (filterUnits), the primitive units and the primitives; each primitive's
// attributes become a filter::Primitive in the filtered element's user space. What the resvg
// test suite shows for invalid input is followed: a filter that names nothing, has no
// primitives, an empty region or bounding box with objectBoundingBox units, a subregion of zero
// or negative size or an unusable primitive hides the element; an `in` naming no earlier result
// reads the previous result (SourceGraphic for the first primitive); BackgroundImage,
// BackgroundAlpha, FillPaint and StrokePaint read SourceGraphic.
#include "formats/svg/filter_graphs.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <map>

#include "casteljau/error.hpp"
#include "casteljau/limits.hpp"

namespace casteljau::svg_filter {

namespace {

std::string_view trim(std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    return s;
}

// Whitespace- and comma-separated numbers; nullopt when any item is not a finite number.
std::optional<std::vector<double>> numbers(std::string_view s) {
    std::vector<double> out;
    std::size_t i = 0;
    while (i < s.size()) {
        while (i < s.size() && (std::isspace(static_cast<unsigned char>(s[i])) || s[i] == ',')) ++i;
        if (i >= s.size()) break;
        const char* b = s.data() + i;
        if (*b == '+') ++b;
        double v;
        const auto r = std::from_chars(b, s.data() + s.size(), v);
        if (r.ec != std::errc() || !std::isfinite(v)) return std::nullopt;
        const std::size_t end = static_cast<std::size_t>(r.ptr - s.data());
        if (end < s.size() && !std::isspace(static_cast<unsigned char>(s[end])) && s[end] != ',') return std::nullopt;
        out.push_back(v);
        i = end;
    }
    return out;
}

std::optional<double> number(std::string_view s) {
    auto v = numbers(s);
    if (!v || v->size() != 1) return std::nullopt;
    return (*v)[0];
}

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

// A number or a percentage (as a fraction), for objectBoundingBox units.
std::optional<double> fraction(std::string_view s) {
    s = trim(s);
    if (s.empty()) return std::nullopt;
    if (s.back() == '%') {
        auto v = number(s.substr(0, s.size() - 1));
        if (!v) return std::nullopt;
        return *v / 100;
    }
    return number(s);
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

std::array<double, 20> identity_matrix() {
    std::array<double, 20> m{};
    m[0] = m[6] = m[12] = m[18] = 1;
    return m;
}

std::array<double, 20> saturate_matrix(double s) {
    return {0.213 + 0.787 * s,
            0.715 - 0.715 * s,
            0.072 - 0.072 * s,
            0,
            0,
            0.213 - 0.213 * s,
            0.715 + 0.285 * s,
            0.072 - 0.072 * s,
            0,
            0,
            0.213 - 0.213 * s,
            0.715 - 0.715 * s,
            0.072 + 0.928 * s,
            0,
            0,
            0,
            0,
            0,
            1,
            0};
}

std::array<double, 20> hue_rotate_matrix(double degrees) {
    const double r = degrees * kPi / 180, c = std::cos(r), s = std::sin(r);
    return {0.213 + c * 0.787 - s * 0.213,
            0.715 - c * 0.715 - s * 0.715,
            0.072 - c * 0.072 + s * 0.928,
            0,
            0,
            0.213 - c * 0.213 + s * 0.143,
            0.715 + c * 0.285 + s * 0.140,
            0.072 - c * 0.072 - s * 0.283,
            0,
            0,
            0.213 - c * 0.213 - s * 0.787,
            0.715 - c * 0.715 + s * 0.715,
            0.072 + c * 0.928 + s * 0.072,
            0,
            0,
            0,
            0,
            0,
            1,
            0};
}

std::array<double, 20> luminance_to_alpha_matrix() {
    std::array<double, 20> m{};
    m[15] = 0.2125;
    m[16] = 0.7154;
    m[17] = 0.0721;
    return m;
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
            l.specular_exponent = number_attr(c, "specularExponent", 1);
            if (c.attribute("limitingConeAngle")) {
                auto a = number(c.attribute("limitingConeAngle").value());
                if (a) l.cone_angle = *a;
            }
            return true;
        }
    }
    return false;
}

// feColorMatrix: its type and values (an invalid list leaves the identity).
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
    } else if (type.empty() || type == "matrix") {
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
    double sum = 0;
    for (double v : p.kernel) sum += v;
    p.divisor = sum == 0 ? 1 : sum;
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

// The filter primitive element `n` read into `p`; false when it is unknown or invalid.
bool read_primitive(const pugi::xml_node& n, const Units& u, const SvgFilterEnv& env, filter::Primitive& p) {
    using P = filter::Primitive;
    const std::string_view name = n.name();
    if (name == "feFlood") {
        p.op = P::Flood;
        p.color = flood_color(n, env, "flood-color", "flood-opacity", Color::black());
    } else if (name == "feOffset") {
        p.op = P::Offset;
        p.dx = u.lx(number_attr(n, "dx", 0));
        p.dy = u.ly(number_attr(n, "dy", 0));
    } else if (name == "feMerge") {
        p.op = P::Merge;
    } else if (name == "feBlend") {
        p.op = P::Blend;
        const std::string mode = std::string(trim(n.attribute("mode").value()));
        if (!mode.empty() && !parse_blend_mode(mode, p.blend)) p.blend = BlendMode::Normal;
    } else if (name == "feComposite") {
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
    } else if (name == "feGaussianBlur" || name == "feDropShadow") {
        p.op = name == "feGaussianBlur" ? P::GaussianBlur : P::DropShadow;
        auto sd = number_pair(n, "stdDeviation");
        double sx = p.op == P::DropShadow ? 2 : 0, sy = sx;
        if (sd) {
            sx = sd->first;
            sy = sd->second;
        }
        if (sx < 0 || sy < 0) sx = sy = 0;  // a negative deviation disables the blur
        p.std_x = u.lx(sx);
        p.std_y = u.ly(sy);
        p.edge = edge_mode(n, filter::EdgeMode::None);
        if (p.op == P::DropShadow) {
            p.dx = u.lx(number_attr(n, "dx", 2));
            p.dy = u.ly(number_attr(n, "dy", 2));
            p.color = flood_color(n, env, "flood-color", "flood-opacity", Color::black());
        }
    } else if (name == "feColorMatrix") {
        read_color_matrix(n, p);
    } else if (name == "feComponentTransfer") {
        read_component_transfer(n, p);
    } else if (name == "feMorphology") {
        p.op = P::Morphology;
        p.dilate = trim(n.attribute("operator").value()) == "dilate";
        // A missing, malformed or negative radius, or zero on both axes, is 1 (as resvg does); zero
        // on one axis leaves that axis alone.
        auto r = number_pair(n, "radius");
        if (!r || r->first < 0 || r->second < 0 || (r->first == 0 && r->second == 0)) r = std::pair{1.0, 1.0};
        p.rx = u.lx(r->first);
        p.ry = u.ly(r->second);
    } else if (name == "feConvolveMatrix") {
        if (!read_convolve_matrix(n, p)) return false;
    } else if (name == "feTile") {
        p.op = P::Tile;
    } else if (name == "feImage") {
        p.op = P::Image;
        p.draw = env.image(n, p.subregion);
    } else if (name == "feTurbulence") {
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
    } else if (name == "feDisplacementMap") {
        p.op = P::DisplacementMap;
        p.scale = number_attr(n, "scale", 0);
        if (u.bbox) p.scale *= std::sqrt(u.box.width() * u.box.height());
        auto channel = [&](const char* a) {
            const std::string_view v = trim(n.attribute(a).value());
            return v == "R" ? 0 : v == "G" ? 1 : v == "B" ? 2 : 3;
        };
        p.x_channel = channel("xChannelSelector");
        p.y_channel = channel("yChannelSelector");
    } else if (name == "feDiffuseLighting" || name == "feSpecularLighting") {
        p.op = name == "feDiffuseLighting" ? P::DiffuseLighting : P::SpecularLighting;
        p.surface_scale = number_attr(n, "surfaceScale", 1);
        p.diffuse_constant = number_attr(n, "diffuseConstant", 1);
        p.specular_constant = number_attr(n, "specularConstant", 1);
        p.specular_exponent = number_attr(n, "specularExponent", 1);
        if (p.op == P::SpecularLighting && !(p.specular_exponent >= 1 && p.specular_exponent <= 128)) return false;
        p.color = flood_color(n, env, "lighting-color", "lighting-opacity", Color::white());
        if (!read_light(n, u, p.light)) return false;
    } else {
        return false;
    }
    return true;
}

}  // namespace

std::optional<filter::FilterGraph> build_filter(const pugi::xml_node& f, const std::optional<Rect>& bbox,
                                                const SvgFilterEnv& env) {
    std::vector<pugi::xml_node> chain{f};
    while (chain.size() < 32) {
        const pugi::xml_node& last = chain.back();
        const char* h = last.attribute("href").value();
        if (!*h) h = last.attribute("xlink:href").value();
        if (*h != '#') break;
        const pugi::xml_node next = env.lookup(h + 1);
        if (!next || std::string_view(next.name()) != "filter" ||
            std::find(chain.begin(), chain.end(), next) != chain.end())
            break;
        chain.push_back(next);
    }
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
        const double vsize = (std::string_view(name) == "x" || std::string_view(name) == "width") ? env.vw : env.vh;
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
            auto l = env.length(at.value(), horizontal ? env.vw : env.vh);
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

std::optional<std::vector<FilterRef>> parse_filter_property(std::string_view value) {
    std::vector<FilterRef> out;
    std::string_view s = trim(value);
    while (!s.empty()) {
        std::size_t i = 0;
        while (i < s.size() && (std::isalnum(static_cast<unsigned char>(s[i])) || s[i] == '-')) ++i;
        if (i == 0 || i >= s.size() || s[i] != '(') return std::nullopt;
        std::string name(s.substr(0, i));
        std::transform(name.begin(), name.end(), name.begin(),
                       [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
        int depth = 0;
        std::size_t j = i;
        for (; j < s.size(); ++j) {
            if (s[j] == '(')
                ++depth;
            else if (s[j] == ')' && --depth == 0)
                break;
        }
        if (j >= s.size()) return std::nullopt;
        std::string_view inner = trim(s.substr(i + 1, j - i - 1));
        FilterRef r;
        if (name == "url") {
            if (inner.size() >= 2 && (inner.front() == '\'' || inner.front() == '"'))
                inner = inner.substr(1, inner.size() - 2);
            if (inner.empty() || inner.front() != '#') return std::nullopt;
            r.url = std::string(inner.substr(1));
        } else {
            r.function = name;
            // Arguments split at top-level whitespace and commas (rgb(...) stays whole).
            std::string cur;
            int d = 0;
            for (char c : inner) {
                if (c == '(') ++d;
                if (c == ')') --d;
                if (d == 0 && c == ',') r.commas = true;
                if (d == 0 && (std::isspace(static_cast<unsigned char>(c)) || c == ',')) {
                    if (!cur.empty()) r.args.push_back(cur);
                    cur.clear();
                } else {
                    cur += c;
                }
            }
            if (!cur.empty()) r.args.push_back(cur);
        }
        out.push_back(std::move(r));
        s = trim(s.substr(j + 1));
    }
    if (out.empty()) return std::nullopt;
    return out;
}

std::optional<filter::FilterGraph> build_function(const FilterRef& fn, const std::optional<Rect>& bbox,
                                                  const SvgFilterEnv& env) {
    using P = filter::Primitive;
    filter::FilterGraph g;
    // The region of a filter function: -10% .. 110% of the viewport in user space (as resvg
    // does), so that shadows and blurs are not cut at the element's bounding box.
    (void)bbox;
    g.region = Rect::from_xywh(-0.1 * env.vw, -0.1 * env.vh, 1.2 * env.vw, 1.2 * env.vh);
    P p;
    p.linear_rgb = false;
    p.subregion = g.region;
    const std::string& name = fn.function;
    if (fn.commas) return std::nullopt;
    // An amount: a number or a percentage; `def` when absent.
    auto amount = [&](double def) -> std::optional<double> {
        if (fn.args.empty()) return def;
        if (fn.args.size() > 1) return std::nullopt;
        auto v = fraction(fn.args[0]);
        if (!v || *v < 0) return std::nullopt;
        return v;
    };
    if (name == "grayscale" || name == "sepia" || name == "saturate" || name == "invert" || name == "opacity" ||
        name == "brightness" || name == "contrast") {
        auto a = amount(1);
        if (!a) return std::nullopt;
        double v = *a;
        if (name != "saturate" && name != "brightness" && name != "contrast") v = std::min(v, 1.0);
        if (name == "grayscale" || name == "sepia") {
            // The full effect's 3x3 colour matrix T, applied in proportion v: T + (1 - v) (I - T).
            static constexpr double kGray[9] = {0.2126, 0.7152, 0.0722, 0.2126, 0.7152, 0.0722, 0.2126, 0.7152, 0.0722};
            static constexpr double kSepia[9] = {0.393, 0.769, 0.189, 0.349, 0.686, 0.168, 0.272, 0.534, 0.131};
            const double* t = name == "grayscale" ? kGray : kSepia;
            p.op = P::ColorMatrix;
            p.matrix = identity_matrix();
            for (int r = 0; r < 3; ++r)
                for (int c = 0; c < 3; ++c)
                    p.matrix[static_cast<std::size_t>(r * 5 + c)] =
                        t[r * 3 + c] + (1 - v) * ((r == c ? 1.0 : 0.0) - t[r * 3 + c]);
        } else if (name == "saturate") {
            p.op = P::ColorMatrix;
            p.matrix = saturate_matrix(v);
        } else {
            p.op = P::ComponentTransfer;
            filter::TransferFunction t;
            if (name == "invert") {
                t.type = filter::TransferFunction::Table;
                t.table = {v, 1 - v};
            } else if (name == "opacity") {
                t.type = filter::TransferFunction::Table;
                t.table = {0, v};
            } else {
                t.type = filter::TransferFunction::Linear;
                t.slope = v;
                t.intercept = name == "contrast" ? 0.5 - 0.5 * v : 0;
            }
            if (name == "opacity")
                p.funcs[3] = t;
            else
                p.funcs[0] = p.funcs[1] = p.funcs[2] = t;
        }
    } else if (name == "hue-rotate") {
        double deg = 0;
        if (fn.args.size() > 1) return std::nullopt;
        if (!fn.args.empty()) {
            std::string_view a = trim(fn.args[0]);
            std::size_t k = 0;
            while (k < a.size() && (std::isdigit(static_cast<unsigned char>(a[k])) || a[k] == '.' || a[k] == '-' ||
                                    a[k] == '+' || a[k] == 'e' || a[k] == 'E'))
                ++k;
            auto v = number(a.substr(0, k));
            const std::string_view unit = a.substr(k);
            if (!v) return std::nullopt;
            // A unitless angle other than 0 is invalid CSS.
            if (unit == "deg" || (unit.empty() && *v == 0))
                deg = *v;
            else if (unit == "grad")
                deg = *v * 0.9;
            else if (unit == "rad")
                deg = *v * 180 / kPi;
            else if (unit == "turn")
                deg = *v * 360;
            else
                return std::nullopt;
        }
        p.op = P::ColorMatrix;
        p.matrix = hue_rotate_matrix(deg);
    } else if (name == "blur") {
        double sd = 0;
        if (fn.args.size() > 1) return std::nullopt;
        if (!fn.args.empty()) {
            if (trim(fn.args[0]).back() == '%') return std::nullopt;
            auto l = env.length(fn.args[0], 0);
            if (!l || *l < 0) return std::nullopt;
            sd = *l;
        }
        p.op = P::GaussianBlur;
        p.std_x = p.std_y = sd;
    } else if (name == "drop-shadow") {
        p.op = P::DropShadow;
        p.color = env.current_color;
        std::vector<double> lengths;
        bool have_color = false;
        for (const std::string& a : fn.args) {
            if (auto l = env.length(a, 0); l && trim(a).back() != '%') {
                lengths.push_back(*l);
                continue;
            }
            if (have_color) return std::nullopt;
            try {
                p.color = trim(a) == "currentColor" ? env.current_color : env.color(a);
            } catch (const Error&) { return std::nullopt; }
            have_color = true;
        }
        if (lengths.size() == 1 || lengths.size() > 3) return std::nullopt;
        p.dx = lengths.size() >= 2 ? lengths[0] : 0;
        p.dy = lengths.size() >= 2 ? lengths[1] : 0;
        p.std_x = p.std_y = lengths.size() == 3 ? std::max(0.0, lengths[2]) : 0;
        if (lengths.size() == 3 && lengths[2] < 0) return std::nullopt;
    } else {
        return std::nullopt;
    }
    g.primitives.push_back(std::move(p));
    return g;
}

}  // namespace casteljau::svg_filter
