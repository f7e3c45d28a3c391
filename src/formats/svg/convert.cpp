// Formats stage, SVG conversion: a whole document, from its bytes to its display list. Reads the
// XML (inflating .svgz), sizes the output from the root's width, height and viewBox, then converts
// the root like any group with one Context (context.hpp).
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>

#include "casteljau/error.hpp"
#include "casteljau/paint.hpp"
#include "formats/svg/context.hpp"
#include "formats/svg/display_list.hpp"
#include "formats/svg/values.hpp"
#include "formats/svg/xml_input.hpp"

namespace casteljau::svg {

namespace {

// Parses `input` (gzip-compressed or not) into `xml`; returns its root <svg> element.
pugi::xml_node read_xml(std::string_view input, pugi::xml_document& xml) {
    std::string inflated;
    if (input.size() >= 2 && static_cast<unsigned char>(input[0]) == 0x1f &&
        static_cast<unsigned char>(input[1]) == 0x8b)
        inflated = gunzip(input);
    std::string_view text = inflated.empty() ? input : std::string_view(inflated);
    const std::string expanded = expand_entities(text);
    if (!expanded.empty()) text = expanded;
    if (trim(text).empty()) throw Error(ErrorKind::Parse, "SVG input is empty");
    const pugi::xml_parse_result res = xml.load_buffer(
        text.data(), text.size(), pugi::parse_default | pugi::parse_ws_pcdata);  // text needs the spaces between tspans
    if (!res)
        throw Error(ErrorKind::Parse, std::string("malformed SVG (XML) at byte ") + std::to_string(res.offset) + ": " +
                                          res.description());
    normalise_namespaces(xml.document_element(), {});
    const pugi::xml_node root = xml.document_element();
    if (std::string_view(root.name()) != "svg")
        throw Error(ErrorKind::InvalidData, std::string("root element is <") + root.name() + ">, expected <svg>");
    return root;
}

// The document's size from the root's width, height and viewBox `vb` (out.width .. out.fheight),
// physical units at `dpi`.
void size_document(const pugi::xml_node& root, const std::optional<Rect>& vb, double dpi, ConvertedDocument& out) {
    auto root_length = [&](const char* name, double vb_size) -> std::optional<double> {
        const char* v = root.attribute(name).value();
        if (!*v) return std::nullopt;
        auto l = parse_length(v, vb_size, kUnknownFontSize, dpi);
        if (!l) throw Error(ErrorKind::InvalidData, std::string("invalid <svg> ") + name + " '" + v + "'");
        return l;
    };
    std::optional<double> w = root_length("width", vb ? vb->width() : 100);
    std::optional<double> h = root_length("height", vb ? vb->height() : 100);
    if (!w) w = vb ? vb->width() : 100.0;
    if (!h) h = vb ? vb->height() : 100.0;
    if (!(*w > 0) || !(*h > 0))
        throw Error(ErrorKind::InvalidData,
                    "SVG width and height must be positive, got " + std::to_string(*w) + " x " + std::to_string(*h));
    // The output size is the intrinsic size rounded to whole pixels (at least 1), as resvg does;
    // the fractional size stays for the scale (render() fills the whole output).
    const double rw = std::max(1.0, std::round(*w)), rh = std::max(1.0, std::round(*h));
    check_canvas_size(rw, rh);
    out.width = static_cast<int>(rw);
    out.height = static_cast<int>(rh);
    out.fwidth = *w;
    out.fheight = *h;
}

// The root's background-color (CSS backgrounds: the root element's background covers the whole
// canvas): a fill of the output rectangle under everything, in document pixels.
void background(Context& cx, const pugi::xml_node& root, const ConvertedDocument& out) {
    std::string value;
    for (const auto& [k, v] : properties(cx, root))
        if (k == "background-color") value = std::string(trim(v));
    if (value.empty()) return;
    Color c;
    try {
        c = parse_color(value);
    } catch (const Error&) {
        warn(cx, "invalid background-color '" + value + "' ignored");
        return;
    }
    if (c.a == 0) return;
    DisplayItem it;
    it.kind = DisplayItem::Fill;
    it.path.add_rect(Rect{0, 0, out.fwidth, out.fheight});
    it.color = c;
    cx.items.push_back(std::move(it));
}

}  // namespace

ConvertedDocument convert_document(std::string_view input, const SvgOptions& options, std::string_view source) {
    if (!(options.dpi >= SvgOptions::kMinDpi && options.dpi <= SvgOptions::kMaxDpi))
        throw Error(ErrorKind::InvalidArgument, "SVG dpi must be between 1 and 10000");
    pugi::xml_document xml;
    const pugi::xml_node root = read_xml(input, xml);
    ConvertedDocument out;
    const char* vb_text = root.attribute("viewBox").value();
    const std::optional<Rect> vb = parse_viewbox(vb_text);
    if (!vb && *vb_text) out.warnings.push_back(std::string("invalid viewBox '") + vb_text + "' ignored");
    size_document(root, vb, options.dpi, out);

    // viewBox -> viewport with preserveAspectRatio.
    Viewport vp{out.fwidth, out.fheight};
    if (vb) {
        vp = {vb->width(), vb->height()};
        out.view = viewbox_transform(*vb, root.attribute("preserveAspectRatio").value(), out.fwidth, out.fheight);
    }

    Context cx;
    cx.options = options;
    index_ids(cx, root);
    find_export_target(cx, root, source);
    read_style_sheets(cx, root);
    if (cx.export_path.empty()) background(cx, root, out);  // the root's own painting: not of an exported element
    cut_recursive_links(cx, root);
    // The root goes through the element path like any group: its conditional processing,
    // transform, display, opacity, clip-path, mask, filter and blending apply to the whole document.
    if (conditions_pass(root)) element(cx, root, initial_style(options), out.view, vp, 0);
    warn_export_not_reached(cx);
    out.items = std::move(cx.items);
    out.warnings.insert(out.warnings.end(), cx.warnings.begin(), cx.warnings.end());
    return out;
}

}  // namespace casteljau::svg
