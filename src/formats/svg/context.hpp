// Internal (formats): converting an SVG document tree into a display list (display_list.hpp).
//
// Conversion walks the element tree once (structure.cpp) with one Context: the document's
// options, limits and warnings, its style sheet and caches of the cascade, the ids, the guards
// against reference cycles and expansion bombs, and the display list being produced. Each
// element's computed painting properties travel down the tree in a Style; lengths resolve against
// the nearest Viewport. Each SVG feature has its own file, declared below in the order a newcomer
// meets them: the cascade, style, shapes, the tree, use, paint servers, patterns, clips and masks,
// markers, images, filters and text.
//
// Coordinates: every function takes `m` / `cm`, the transform from the element's user space to
// document pixels (the root's viewBox mapping included); paths stay in user space.
// Thread-safety: a Context belongs to one conversion on one thread.
#pragma once

#include <pugixml.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

#include "casteljau/error.hpp"
#include "casteljau/filter.hpp"
#include "casteljau/limits.hpp"
#include "casteljau/paint.hpp"
#include "casteljau/stroke.hpp"
#include "casteljau/svg.hpp"
#include "formats/svg/css.hpp"
#include "formats/svg/display_list.hpp"
#include "formats/svg/filter_graphs.hpp"
#include "formats/svg/references.hpp"
#include "formats/svg/values.hpp"

namespace casteljau::svg_text {
class FontSet;
struct Outline;
struct ColorGlyph;
}  // namespace casteljau::svg_text

namespace casteljau::svg {

// The element a context-fill or context-stroke paint comes from (the shape a marker is drawn on,
// or a use element): a paint server is resolved for its bounding box (the bounds of `path`) in its
// user space (`transform`: that space -> document pixels; `viewport` its viewport).
struct ContextElement {
    Path path;
    Affine transform;
    Viewport viewport;
};

// A fill or stroke as specified: none, a colour, or a paint server (url(#id)) with its fallback.
struct PaintRef {
    enum Kind { None, Solid, Server } kind = None;
    Color color = Color::black();
    std::string id;        // Server: the referenced element's id
    Kind fallback = None;  // Server: what to paint when the reference is unusable
    Color fallback_color = Color::black();
    // currentColor as the colour (or the fallback colour): it computes to the `color` of each
    // element the paint is inherited by, so it follows a `color` set further down the tree.
    bool current = false, fallback_current = false;
    std::shared_ptr<const ContextElement> context;  // Server: set when the paint is context-fill/-stroke
    static PaintRef solid(Color c) {
        PaintRef p;
        p.kind = Solid;
        p.color = c;
        return p;
    }
};

// The font size where no element sets one: resvg's default, the size the text engine starts from.
constexpr double kDefaultFontSize = 12;

// The computed painting properties of an element, inherited down the tree.
struct Style {
    PaintRef fill = PaintRef::solid(Color::black());
    Color color = Color::black();  // currentColor
    FillRule fill_rule = FillRule::NonZero;
    double fill_opacity = 1;
    PaintRef stroke;  // none (the SVG default)
    double stroke_opacity = 1;
    StrokeStyle stroke_style;
    bool visible = true;                               // visibility (inherited)
    std::array<int, 3> paint_order{0, 1, 2};           // paint-order: 0 fill, 1 stroke, 2 markers (inherited)
    std::string marker_start, marker_mid, marker_end;  // marker ids (inherited)
    // What context-fill and context-stroke name: the fill and stroke of the use element or of the
    // shape a marker is drawn on (none outside those).
    PaintRef context_fill, context_stroke;
    // The nearest viewport: percentages of stroke-width, stroke-dasharray and stroke-dashoffset are
    // of its normalised diagonal.
    Viewport viewport;
    double font_size = kDefaultFontSize;  // the element's computed font-size (em in filter functions)
};

// The style the document's root inherits: the initial values, with the colour and the context
// paint the host gives (SvgOptions::color, SvgOptions::context_fill).
inline Style initial_style(const SvgOptions& options) {
    Style st;
    st.color = options.color;
    if (options.context_fill) st.context_fill = PaintRef::solid(*options.context_fill);
    return st;
}

// An element's properties after the cascade: (name, value) pairs, later ones winning.
using Properties = std::vector<std::pair<std::string, std::string>>;

// The state of one document's conversion.
struct Context {
    DisplayList items;  // the output: what the elements converted so far became
    std::vector<std::string> warnings;
    const Limits limits = current_limits();  // read once per document
    SvgOptions options;

    // The cascade (cascade.cpp): all <style> elements of the document in order, and the
    // properties and computed font size of each element met so far.
    css::StyleSheet sheet;
    std::unordered_map<const void*, Properties> property_cache;
    std::unordered_map<const void*, double> font_size_cache;
    // Element ids of the whole document (the first element with an id wins).
    std::unordered_map<std::string, pugi::xml_node> ids;

    // Elements drawn or expanded so far (each `use` copy counts again): the bound on use bombs.
    std::size_t expanded = 0;
    // The `use` elements being expanded (innermost last): a use whose target contains one of
    // them, or is one of them, is a cycle.
    std::vector<pugi::xml_node> use_stack;
    bool measuring_use = false;  // inside the first pass that measures a use element's box
    // clip-path, mask, marker, pattern and filter references being expanded: a reference back to
    // one of them is a cycle.
    std::vector<pugi::xml_node> active_refs;
    // The elements whose filters are being built, and whether an feImage named one of them (the
    // filter is then ignored and the element drawn unfiltered, as resvg does).
    std::vector<pugi::xml_node> filtering;
    bool filter_self_reference = false;
    int paint_depth = 0;  // patterns inside pattern content

    // SvgOptions::export_id (export.cpp): the element drawn alone and its ancestors, the element
    // first (empty: the whole document is drawn, or the element's own content is being drawn),
    // and whether the walk reached the element.
    std::vector<pugi::xml_node> export_path;
    bool export_reached = false;

    // Text (text.cpp): the fonts, opened when the first text is laid out, and the characters of
    // all text laid out so far (use copies too).
    std::shared_ptr<svg_text::FontSet> font_set;
    std::size_t text_chars_total = 0;
};

// A path that counts in bounding boxes without being drawn.
inline DisplayItem bounds_item(Path path, const Affine& transform) {
    DisplayItem it;
    it.kind = DisplayItem::Bounds;
    it.path = std::move(path);
    it.transform = transform;
    return it;
}

// A BeginLayer or EndLayer item (or another item of `kind` with only an opacity).
inline DisplayItem layer_item(DisplayItem::Kind kind, double opacity) {
    DisplayItem it;
    it.kind = kind;
    it.opacity = opacity;
    return it;
}

// A clip to `r` (user space of `m`) around the items that `draw` adds.
template <class F>
void clipped(Context& cx, const Rect& r, const Affine& m, F&& draw) {
    DisplayItem push;
    push.kind = DisplayItem::PushClip;
    push.path.add_rect(r);
    push.transform = m;
    cx.items.push_back(std::move(push));
    draw();
    DisplayItem pop;
    pop.kind = DisplayItem::PopClip;
    cx.items.push_back(std::move(pop));
}

// cascade.cpp: the CSS cascade of an element (presentation attributes, style sheets, the style
// attribute), computed font sizes, ids and references.
void warn(Context& cx, const std::string& w);
const Properties& properties(Context& cx, const pugi::xml_node& node);
void read_style_sheets(Context& cx, const pugi::xml_node& root);
double font_size_of(Context& cx, const pugi::xml_node& node);
void index_ids(Context& cx, const pugi::xml_node& root);
pugi::xml_node lookup(const Context& cx, std::string_view id);
std::string own_property(Context& cx, const pugi::xml_node& n, const std::string& name);
std::string inherited(Context& cx, pugi::xml_node n, const std::string& name);
std::string own_overflow(Context& cx, const pugi::xml_node& n);
bool is_active(const Context& cx, const pugi::xml_node& n);
pugi::xml_node reference(Context& cx, const pugi::xml_node& n, const char* property, std::string_view want,
                         bool& missing);
void override_property(Context& cx, const pugi::xml_node& n, const std::string& name, const std::string& value);

// recursive_links.cpp: references that lead back into a mask from its own content replaced by
// none before conversion (the rest of the content is still drawn).
void cut_recursive_links(Context& cx, const pugi::xml_node& root);

// style.cpp: fill, stroke and the other painting properties of an element resolved into a Style.
void apply_paint(Context& cx, const std::string& property, std::string_view value, Color current, PaintRef& paint);
void apply_style(Context& cx, const pugi::xml_node& node, Style& st);
PaintRef context_paint(PaintRef paint, const std::shared_ptr<const ContextElement>& context);

// shapes.cpp: the geometry of the basic shapes and length attributes.
double length_attr(Context& cx, const pugi::xml_node& n, const char* name, double percent_of, double fallback = 0);
std::optional<Path> shape_path(Context& cx, const pugi::xml_node& n, Viewport vp);

// structure.cpp: the element tree: containers, nested viewports, conditional processing,
// transforms, and what each element becomes (layers for opacity, clips, masks, filters, blending).
void walk(Context& cx, const pugi::xml_node& node, const Style& st, const Affine& m, Viewport vp, int depth);
bool known_element(std::string_view n);
bool conditions_pass(const pugi::xml_node& n);
Affine with_origin(Context& cx, const pugi::xml_node& n, const Affine& t, Viewport vp);
Affine element_transform(Context& cx, const pugi::xml_node& n, Viewport vp);
void viewport(Context& cx, const pugi::xml_node& n, const Style& st, const Affine& m, double x, double y, double w,
              double h, int depth, bool is_symbol);
std::optional<Rect> items_bbox(const Context& cx, std::size_t first, const Affine& m);
void element(Context& cx, const pugi::xml_node& child, const Style& st, const Affine& m, Viewport vp, int depth);
void content(Context& cx, const pugi::xml_node& child, const Style& cst, const Affine& cm, Viewport vp, int depth,
             double opacity);

// export.cpp: SvgOptions::export_id: the element drawn alone, and the walk restricted to the
// elements on the way to it from the root.
void find_export_target(Context& cx, const pugi::xml_node& root, std::string_view source);
void export_child(Context& cx, const pugi::xml_node& parent, const pugi::xml_node& child, const Style& st,
                  const Affine& m, Viewport vp, int depth);
void warn_export_not_reached(Context& cx);

// use.cpp: the use element: instancing an element, a symbol or an svg, with reference-cycle checks
// and the context element of context-fill and context-stroke.
void use(Context& cx, const pugi::xml_node& u, const Style& st, const Affine& m, Viewport vp, int depth);

// paint_servers.cpp: paints resolved for a shape: solid colours and the linearGradient and
// radialGradient paint servers.
bool resolve_paint(Context& cx, const PaintRef& ref, const Path& path, const Affine& cm, Viewport vp, DisplayItem& it);
bool resolve_paint(Context& cx, const PaintRef& ref, const Path& path, Viewport vp, DisplayItem& it);
bool gradient(Context& cx, const pugi::xml_node& node, const Path& path, Viewport vp, DisplayItem& it);

// pattern.cpp: the pattern paint server: its tile content converted into a PatternTile.
bool pattern(Context& cx, const pugi::xml_node& node, const Path& path, Viewport vp, DisplayItem& it);

// clip_mask.cpp: clipPath and mask content converted into mask layers.
void emit_clip(Context& cx, const pugi::xml_node& clip, const Affine& cm, const std::optional<Rect>& box, Viewport vp,
               int depth);
void clip_child(Context& cx, const pugi::xml_node& c, const Affine& m, FillRule rule, Viewport vp, int depth);
void emit_mask(Context& cx, const pugi::xml_node& mask, const Affine& cm, const std::optional<Rect>& box, Viewport vp,
               int depth);

// markers.cpp: markers drawn at the vertices of a shape.
void emit_markers(Context& cx, const Path& path, const Style& st, const Affine& cm, Viewport vp, int depth);
void emit_marker(Context& cx, const pugi::xml_node& marker, const Style& st,
                 const std::shared_ptr<const ContextElement>& context, const Affine& at, Viewport vp, int depth);

// image.cpp: the image element: raster images and SVG documents from data: URIs or files beside
// the document.
std::optional<std::vector<std::uint8_t>> image_bytes(Context& cx, std::string_view ref);
void image(Context& cx, const pugi::xml_node& n, const Style& st, const Affine& cm, Viewport vp, double opacity);

// filters.cpp: the glue between an element and its filters (filter_graphs.hpp builds the graphs).
// An element's filters: the steps of its `filter` property (nullopt: not filtered) and the
// <filter> elements they name.
struct ElementFilters {
    std::optional<std::vector<svg_filter::FilterRef>> refs;
    std::vector<pugi::xml_node> nodes;
};
// The filters of `child` with its style `cst`: an invalid function or a recursive filter is
// ignored (with a warning); nullopt when the element is not drawn (a lone url naming no filter).
std::optional<ElementFilters> element_filters(Context& cx, const pugi::xml_node& child, const Style& cst, Viewport vp,
                                              int depth);
// Ends the filtered content that starts with the BeginFilter item at `filter_first`: the
// EndFilter item with the graphs built for the content's bounding box in the user space of `cm`.
// When an feImage draws the filtered element itself, the filter is ignored (BeginFilter removed).
// False when a filter is invalid: the element is not drawn.
bool finish_filters(Context& cx, const pugi::xml_node& child, const ElementFilters& filters, std::size_t filter_first,
                    const Affine& cm, const Style& cst, Viewport vp, int depth);
std::optional<std::vector<svg_filter::FilterRef>> filter_refs(Context& cx, const pugi::xml_node& n);
svg_filter::SvgFilterEnv filter_env(Context& cx, const Style& st, Viewport vp, int depth);
std::optional<std::vector<filter::FilterGraph>> build_filters(Context& cx,
                                                              const std::vector<svg_filter::FilterRef>& refs,
                                                              const std::optional<Rect>& bbox, const Style& st,
                                                              Viewport vp, int depth);

// text.cpp: text elements converted into glyph outlines, painted as fills and strokes
// (text_properties.hpp: the text properties and the layout input).
void text(Context& cx, const pugi::xml_node& node, const Style& st, const Affine& cm, Viewport vp, double opacity);
std::vector<svg_text::Outline> text_outlines(Context& cx, const pugi::xml_node& node, const Style& st, Viewport vp,
                                             std::vector<Style>& styles, std::optional<Rect>* box = nullptr,
                                             std::vector<svg_text::ColorGlyph>* color = nullptr);

}  // namespace casteljau::svg
