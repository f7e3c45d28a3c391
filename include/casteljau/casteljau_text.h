/* casteljau/casteljau_text.h: paragraph layout through the C API (plain C99; casteljau.h includes
 * it).
 *
 * A layout is UTF-8 text shaped by HarfBuzz and laid out with a fallback chain of fonts (each
 * character from the first font that has it), broken into lines at newlines and, with a wrap width,
 * at word boundaries, aligned, in either base direction, with OpenType features and variable-font
 * axis settings: what `casteljau text` draws (casteljau/text.hpp gives the pipeline and its limits).
 *
 * Coordinates: layout space is pixels, x right, y down, (0, 0) the top-left corner of the text
 * box; line i's baseline is at the first font's ascender plus i line advances. Drawing maps layout
 * space to the canvas's user space by a translation to the given origin.
 *
 * Conventions, errors and ownership are those of casteljau.h: every handle here is the caller's,
 * released by its destroy function (which accepts NULL); a NULL handle or out-parameter is
 * CASTELJAU_ERROR_INVALID_ARGUMENT unless a comment says NULL means the defaults.
 * A layout keeps its own copies of the fonts it was made with (sharing their file bytes): the
 * fonts may be destroyed once it is made.
 * Thread-safety: a style or a layout belongs to one thread at a time; making a layout reads its
 * fonts, which must not be in use on another thread meanwhile.
 */
#ifndef CASTELJAU_TEXT_H
#define CASTELJAU_TEXT_H

#include "casteljau.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct casteljau_text_style casteljau_text_style;
typedef struct casteljau_text_layout casteljau_text_layout;

/* --align: START is left for left-to-right paragraphs and right for right-to-left ones. */
typedef CASTELJAU_ENUM(casteljau_text_align){CASTELJAU_ALIGN_START = 0, CASTELJAU_ALIGN_LEFT = 1,
                                             CASTELJAU_ALIGN_CENTER = 2,
                                             CASTELJAU_ALIGN_RIGHT = 3} casteljau_text_align;
/* --direction: AUTO takes each paragraph's base direction from its first strong letter. */
typedef CASTELJAU_ENUM(casteljau_text_direction){CASTELJAU_DIRECTION_AUTO = 0, CASTELJAU_DIRECTION_LTR = 1,
                                                 CASTELJAU_DIRECTION_RTL = 2} casteljau_text_direction;

/* One line of a layout. */
typedef struct casteljau_text_line {
    const char* text; /* the line's characters as UTF-8 (NUL-terminated; valid while the layout lives) */
    size_t length;    /* bytes of `text` */
    double x;         /* left end of the line after alignment */
    double baseline;  /* y of the baseline */
    double width;     /* advance width, trailing spaces excluded */
    int rtl;          /* nonzero when the paragraph's base direction is right to left */
} casteljau_text_line;

/* Styles. A new style: 16 px per em, line height 1, no wrapping, START alignment, AUTO direction,
 * script detected, no language, no feature, no variation, no system font fallback, palette 0.
 * NULL when out of memory. */
CASTELJAU_API casteljau_text_style* casteljau_text_style_create(void);
CASTELJAU_API void casteljau_text_style_destroy(casteljau_text_style* style);
CASTELJAU_API casteljau_status
casteljau_text_style_set_size(casteljau_text_style* style, double size); /* --size: px per em, above 0, at most 10000 */
/* --line-height: the line advance as a multiple of the first font's line spacing, above 0, at most 100. */
CASTELJAU_API casteljau_status casteljau_text_style_set_line_height(casteljau_text_style* style, double line_height);
/* --width: wrap lines at word boundaries to this many pixels (1 to 32768); 0: no wrapping. */
CASTELJAU_API casteljau_status casteljau_text_style_set_width(casteljau_text_style* style, double width);
CASTELJAU_API casteljau_status casteljau_text_style_set_align(casteljau_text_style* style, casteljau_text_align align);
CASTELJAU_API casteljau_status casteljau_text_style_set_direction(casteljau_text_style* style,
                                                                  casteljau_text_direction direction);
/* --script: an ISO 15924 tag ("Latn", "Arab") for every run; NULL or "": detected. */
CASTELJAU_API casteljau_status casteljau_text_style_set_script(casteljau_text_style* style, const char* script);
/* --language: a BCP 47 tag ("en", "tr"); NULL or "": none. */
CASTELJAU_API casteljau_status casteljau_text_style_set_language(casteljau_text_style* style, const char* language);
/* --feature: adds a HarfBuzz feature string ("kern=0", "liga=0", "smcp"); a malformed one is
 * CASTELJAU_ERROR_PARSE when the layout is made. */
CASTELJAU_API casteljau_status casteljau_text_style_add_feature(casteljau_text_style* style, const char* feature);
/* --variation: adds a variable-font axis setting "TAG=VALUE" ("wght=700"), applied to every font
 * of the layout that has the axis (values clamped to its range). CASTELJAU_ERROR_PARSE for a
 * malformed setting here; CASTELJAU_ERROR_FONT, naming the fonts' axes, when the layout is made
 * and no font has the axis. */
CASTELJAU_API casteljau_status casteljau_text_style_add_variation(casteljau_text_style* style, const char* variation);
/* Nonzero: a character cluster no font of the chain has comes from the system's fonts, found
 * through fontconfig (the face fontconfig ranks first for the first font's family, the language,
 * weight and slant, or the "emoji" family for emoji clusters), as `casteljau text` does by
 * default. 0, the default here as in the C++ library (TextStyle::system_fonts): such clusters show
 * the first font's .notdef glyph and the output depends on the given fonts alone (--no-system-fonts). */
CASTELJAU_API casteljau_status casteljau_text_style_set_system_fonts(casteljau_text_style* style, int use);
/* --palette: the CPAL palette colour glyphs (emoji, COLR fonts) are drawn in, 0 to 65535 (0, the
 * default, is the font's first; one the font lacks means 0). Read when the layout is made: its draw
 * and render_image calls use it. */
CASTELJAU_API casteljau_status casteljau_text_style_set_palette(casteljau_text_style* style, int palette);

/* Lays out UTF-8 `text` (invalid bytes show as U+FFFD) with the fallback chain fonts[0..count)
 * (at least one; --font, repeated) and `style` (NULL: a new style's defaults). Empty text gives
 * a layout without lines. CASTELJAU_ERROR_LIMIT past casteljau_limits.text_bytes. */
CASTELJAU_API casteljau_status casteljau_text_layout_create(const char* text, const casteljau_font* const* fonts,
                                                            size_t count, const casteljau_text_style* style,
                                                            casteljau_text_layout** out);
CASTELJAU_API void casteljau_text_layout_destroy(casteljau_text_layout* layout);
/* The text box: the wrap width (or the widest line without wrapping) by the first ascender to the
 * last descender; either pointer may be NULL. */
CASTELJAU_API casteljau_status casteljau_text_layout_size(const casteljau_text_layout* layout, double* width,
                                                          double* height);
/* The box united with the ink of every glyph (what an image must hold to show it all), in layout
 * space; any pointer may be NULL. */
CASTELJAU_API casteljau_status casteljau_text_layout_bounds(const casteljau_text_layout* layout, double* x0, double* y0,
                                                            double* x1, double* y1);
CASTELJAU_API size_t casteljau_text_layout_line_count(const casteljau_text_layout* layout); /* 0 for NULL */
/* Line `index` (0 to count - 1, top to bottom); CASTELJAU_ERROR_INVALID_ARGUMENT past the last. */
CASTELJAU_API casteljau_status casteljau_text_layout_line(const casteljau_text_layout* layout, size_t index,
                                                          casteljau_text_line* out);
/* Draws the layout with its box's top-left corner at (x, y) in the canvas's user space, under its
 * transform and clip, in `paint`. */
CASTELJAU_API casteljau_status casteljau_text_layout_draw(casteljau_text_layout* layout, casteljau_canvas* canvas,
                                                          double x, double y, const casteljau_paint* paint);
/* What `casteljau text` writes: a new image holding the layout's bounds rounded out to whole
 * pixels plus `padding` pixels on every side (0 to 32768; at least 1 x 1 before the padding),
 * filled with `background`, the text drawn in `paint`. */
CASTELJAU_API casteljau_status casteljau_text_layout_render_image(casteljau_text_layout* layout,
                                                                  const casteljau_paint* paint,
                                                                  casteljau_color background, int padding,
                                                                  casteljau_image** out);

#ifdef __cplusplus
}
#endif

#endif /* CASTELJAU_TEXT_H */
