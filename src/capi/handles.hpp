// C API, internal: what the opaque handles of include/casteljau/casteljau.h (and of the SVG, map
// and text headers beside it) hold, and the guard that turns every C++ exception into a status
// and a thread-local message.
#pragma once

#include <cstring>
#include <memory>
#include <new>
#include <optional>
#include <string>
#include <vector>

#include "casteljau/canvas.hpp"
#include "casteljau/casteljau.h"
#include "casteljau/casteljau_map.h"
#include "casteljau/casteljau_svg.h"
#include "casteljau/casteljau_text.h"
#include "casteljau/error.hpp"
#include "casteljau/font.hpp"
#include "casteljau/geojson.hpp"
#include "casteljau/map.hpp"
#include "casteljau/paint.hpp"
#include "casteljau/path.hpp"
#include "casteljau/projection.hpp"
#include "casteljau/stroke.hpp"
#include "casteljau/svg.hpp"
#include "casteljau/text.hpp"
#include "casteljau/tiles.hpp"

struct casteljau_path {
    casteljau::Path path;
};
struct casteljau_stroke {
    casteljau::StrokeStyle style;
};
struct casteljau_paint {
    casteljau::Paint paint;
};
struct casteljau_image {
    casteljau::Pixmap pixmap;
};
struct casteljau_font {
    casteljau::Font font;
};
struct casteljau_canvas {
    std::unique_ptr<casteljau::Canvas> canvas;
};

// SvgOptions with the defaults of `casteljau svg` (system font fallback on).
struct casteljau_svg_options {
    casteljau_svg_options() { options.system_fallback = true; }
    casteljau::SvgOptions options;
};
struct casteljau_svg {
    casteljau::SvgDocument document;
};

struct casteljau_map {
    casteljau::MapData data;
};
struct casteljau_map_style {
    casteljau::MapStyle style;
};
struct casteljau_map_cache {
    casteljau::MapCache cache;
};
// The image options of `casteljau map`, the projection parsed when it is set.
struct casteljau_map_options {
    casteljau::MapOptions options;
    casteljau::MapProjection projection;
};
// The options of `casteljau tiles`: the pyramid's, with the size and scale kept apart because the
// scale also multiplies the buffer and the style's widths.
struct casteljau_tile_options {
    casteljau::TileOptions options;
    int tile_size = 256, scale = 1, buffer = 64;
    std::string name = "casteljau";
};

struct casteljau_text_style {
    casteljau::TextStyle style;
    std::vector<casteljau::Variation> variations;
    int palette = 0;  // TextDrawOptions::palette of the layouts made with this style
};
// A layout with the fonts it points at (copies of the caller's, variations applied) and the
// UTF-8 text of each line.
struct casteljau_text_layout {
    std::vector<std::unique_ptr<casteljau::Font>> fonts;
    casteljau::TextLayout layout;
    std::vector<std::string> line_text;
    int palette = 0;  // TextDrawOptions::palette for drawing it
};

namespace casteljau::capi {

// Records a stop asked for by a caller's callback: CASTELJAU_ERROR_CANCELLED.
struct Cancelled : std::exception {
    const char* what() const noexcept override { return "cancelled by the progress callback"; }
};

// Records `message` as this thread's last error and returns `status`.
casteljau_status fail(casteljau_status status, const char* message) noexcept;
casteljau_status status_of(ErrorKind kind) noexcept;

// Runs `f`, mapping every exception to a status and the thread's last-error message.
template <class F>
casteljau_status guard(F&& f) noexcept {
    try {
        f();
        return CASTELJAU_OK;
    } catch (const Error& e) { return fail(status_of(e.kind()), e.what()); } catch (const Cancelled& e) {
        return fail(CASTELJAU_ERROR_CANCELLED, e.what());
    } catch (const std::bad_alloc&) {
        return fail(CASTELJAU_ERROR_OUT_OF_MEMORY, "out of memory");
    } catch (const std::exception& e) { return fail(CASTELJAU_ERROR_INTERNAL, e.what()); } catch (...) {
        return fail(CASTELJAU_ERROR_INTERNAL, "unknown error");
    }
}

// Throws Error(InvalidArgument) "NAME is NULL" for a null pointer; returns the pointer.
template <class T>
T* need(T* p, const char* name) {
    if (!p) throw Error(ErrorKind::InvalidArgument, std::string(name) + " is NULL");
    return p;
}

// A matrix from the C struct (NULL: identity).
inline Affine affine(const casteljau_matrix* m) { return m ? Affine{m->a, m->b, m->c, m->d, m->e, m->f} : Affine{}; }

// The value a C caller passed for an enum parameter, read as the int it is without an enum-typed
// load: C allows any int there, while in C++ a value outside the enumerators' range is undefined.
template <class E>
int raw_enum(const E& e) {
    static_assert(sizeof(E) == sizeof(int), "C enums are int-sized here");
    int v;
    std::memcpy(&v, &e, sizeof v);
    return v;
}

// The C enums as C++ ones; throw Error(InvalidArgument) for a value outside the enum.
ImageSampling sampling_of(int s);
BlendMode blend_of(int m);

inline Color color(casteljau_color c) { return Color::rgba(c.r, c.g, c.b, c.a); }

// Throws Error(InvalidArgument) "WHAT must be in [LO, HI]" unless lo <= v <= hi (NaN fails).
void check_range(double v, double lo, double hi, const char* what);
// A C string that may be NULL (read as "").
inline std::string text_or_empty(const char* s) { return s ? std::string(s) : std::string(); }

// Creates a T into *out (checked non-null, set to NULL first) from a callable returning a T.
template <class T, class Make>
casteljau_status create(T** out, Make&& make) noexcept {
    if (out) *out = nullptr;
    return guard([&] {
        need(out, "out");
        *out = new T{make()};
    });
}

// A new value-initialized T, or NULL (the thread's last error says why) when that fails.
template <class T>
T* create_default() noexcept {
    T* p = nullptr;
    guard([&] { p = new T(); });
    return p;
}

}  // namespace casteljau::capi
