"""SVG documents (casteljau_svg.h): SvgDocument, render_svg and svg_to_png, with the options of
`casteljau svg` under the same names (--font-dir is font_dir, --skip-system-fonts is
skip_system_fonts, ...)."""
from __future__ import annotations

import ctypes as _c
import os
from typing import Iterable, List, Optional, Sequence, Tuple, Union

from . import (Canvas, Color, Image, PathLike, _check, _color, _Color, _declare, _Handle, _lib, _out, _text)

_vp, _d, _P = _c.c_void_p, _c.c_double, _c.POINTER
_declare([
    ("casteljau_svg_options_create", _vp, []),
    ("casteljau_svg_options_destroy", None, [_vp]),
    ("casteljau_svg_options_set_resources", _c.c_int, [_vp, _c.c_char_p]),
    ("casteljau_svg_options_add_font_dir", _c.c_int, [_vp, _c.c_char_p]),
    ("casteljau_svg_options_add_font_file", _c.c_int, [_vp, _c.c_char_p]),
    ("casteljau_svg_options_set_system_fonts", _c.c_int, [_vp, _c.c_int]),
    ("casteljau_svg_options_set_font_family", _c.c_int, [_vp, _c.c_int, _c.c_char_p]),
    ("casteljau_svg_options_set_dpi", _c.c_int, [_vp, _d]),
    ("casteljau_svg_options_set_export_id", _c.c_int, [_vp, _c.c_char_p]),
    ("casteljau_svg_load", _c.c_int, [_c.c_char_p, _vp, _P(_vp)]),
    ("casteljau_svg_parse", _c.c_int, [_c.c_char_p, _c.c_size_t, _vp, _P(_vp)]),
    ("casteljau_svg_destroy", None, [_vp]),
    ("casteljau_svg_intrinsic_size", _c.c_int, [_vp, _P(_d), _P(_d)]),
    ("casteljau_svg_output_size", _c.c_int, [_vp, _c.c_int, _c.c_int, _d, _P(_c.c_int), _P(_c.c_int)]),
    ("casteljau_svg_warning_count", _c.c_size_t, [_vp]),
    ("casteljau_svg_warning", _c.c_char_p, [_vp, _c.c_size_t]),
    ("casteljau_svg_render", _c.c_int, [_vp, _vp]),
    ("casteljau_svg_render_image", _c.c_int, [_vp, _c.c_int, _c.c_int, _d, _Color, _P(_vp)]),
])

# The generic families, in the order of casteljau_font_generic.
_FAMILIES = ["font_family", "serif_family", "sans_serif_family", "cursive_family", "fantasy_family",
             "monospace_family"]

SvgSource = Union[bytes, bytearray, memoryview, PathLike]


class _Options(_Handle):
    _destroy = _lib.casteljau_svg_options_destroy

    def __init__(self, resources, font_dir, font_file, skip_system_fonts, families, dpi, export_id):
        self._h = _lib.casteljau_svg_options_create()
        if not self._h:
            raise MemoryError("casteljau: out of memory")
        if resources is not None:
            _check(_lib.casteljau_svg_options_set_resources(self._h, os.fsencode(resources)))
        for d in _many(font_dir):
            _check(_lib.casteljau_svg_options_add_font_dir(self._h, os.fsencode(d)))
        for f in _many(font_file):
            _check(_lib.casteljau_svg_options_add_font_file(self._h, os.fsencode(f)))
        _check(_lib.casteljau_svg_options_set_system_fonts(self._h, 0 if skip_system_fonts else 1))
        for i, name in enumerate(_FAMILIES):
            if families.get(name) is not None:
                _check(_lib.casteljau_svg_options_set_font_family(self._h, i, _text(families[name])))
        if dpi is not None:
            _check(_lib.casteljau_svg_options_set_dpi(self._h, float(dpi)))
        if export_id is not None:
            _check(_lib.casteljau_svg_options_set_export_id(self._h, _text(export_id)))


def _many(value) -> Iterable:
    """One value or a sequence of them (a repeatable option)."""
    if value is None:
        return ()
    if isinstance(value, (str, bytes, os.PathLike)):
        return (value,)
    return value


def _is_markup(source) -> bool:
    return isinstance(source, str) and source.lstrip().startswith("<")


class SvgDocument(_Handle):
    """An SVG or .svgz document, read once and drawn any number of times (from several threads at
    once if need be).

    `source` is a file path, the document's bytes, or SVG text (a str starting with "<").
    resources: the folder <image> files may be read from (--resources; default: the file's own
    folder; a document from memory reads no file without it). font_dir, font_file: folders and
    files of fonts for text (one or a list; --font-dir, --font-file). skip_system_fonts: do not use
    the system's fonts (--skip-system-fonts). font_family, serif_family, sans_serif_family,
    cursive_family, fantasy_family, monospace_family: the family names of the generic CSS families
    (--font-family, ...). dpi: pixels per inch of the physical units, the root's size included
    (--dpi; 96 by default, 1 to 10000). export_id: draw only the element with this id (a leading
    '#' is ignored) where it lies in the document, on the document's canvas (--export-id). Raises
    Error for a missing file or font folder, malformed XML (status 2), an unusable root or an
    export_id no element has (status 3), a dpi out of range (status 1)."""
    _destroy = _lib.casteljau_svg_destroy

    def __init__(self, source: SvgSource, *, resources: Optional[PathLike] = None,
                 font_dir: Union[PathLike, Sequence[PathLike], None] = None,
                 font_file: Union[PathLike, Sequence[PathLike], None] = None,
                 skip_system_fonts: bool = False, font_family: Optional[str] = None, serif_family: Optional[str] = None,
                 sans_serif_family: Optional[str] = None, cursive_family: Optional[str] = None,
                 fantasy_family: Optional[str] = None, monospace_family: Optional[str] = None,
                 dpi: Optional[float] = None, export_id: Optional[str] = None) -> None:
        families = dict(font_family=font_family, serif_family=serif_family, sans_serif_family=sans_serif_family,
                        cursive_family=cursive_family, fantasy_family=fantasy_family, monospace_family=monospace_family)
        options = _Options(resources, font_dir, font_file, skip_system_fonts, families, dpi, export_id)
        if isinstance(source, (bytes, bytearray, memoryview)) or _is_markup(source):
            data = source.encode("utf-8") if isinstance(source, str) else bytes(source)
            self._h = _out(_lib.casteljau_svg_parse, data, len(data), options._h)
        else:
            self._h = _out(_lib.casteljau_svg_load, os.fsencode(source), options._h)

    @property
    def intrinsic_size(self) -> Tuple[float, float]:
        """The root's width and height in CSS pixels (96 dpi), fractional."""
        w, h = _d(), _d()
        _check(_lib.casteljau_svg_intrinsic_size(self._h, _c.byref(w), _c.byref(h)))
        return (w.value, h.value)

    def output_size(self, width: Optional[int] = None, height: Optional[int] = None,
                    zoom: Optional[float] = None) -> Tuple[int, int]:
        """The image size `casteljau svg` picks for -w, --height and -z (the intrinsic size rounded,
        at least 1 x 1, when none is given; one side gives the other by the aspect ratio)."""
        w, h = _c.c_int(), _c.c_int()
        _check(_lib.casteljau_svg_output_size(self._h, width or 0, height or 0, zoom or 0.0, _c.byref(w), _c.byref(h)))
        return (w.value, h.value)

    @property
    def warnings(self) -> List[str]:
        """What the reader did not draw or recovered from (unsupported features, path data errors)."""
        n = _lib.casteljau_svg_warning_count(self._h)
        return [_lib.casteljau_svg_warning(self._h, i).decode("utf-8", "replace") for i in range(n)]

    def render(self, canvas: Canvas) -> None:
        """Draws the document onto `canvas` under its transform and clip: one user unit per CSS
        pixel, the viewBox mapped onto (0, 0)-(intrinsic width, intrinsic height)."""
        _check(_lib.casteljau_svg_render(self._h, canvas._h))

    def render_image(self, width: Optional[int] = None, height: Optional[int] = None, zoom: Optional[float] = None,
                     background: Optional[Color] = None, tolerance: Optional[float] = None) -> Image:
        """A new image of output_size(width, height, zoom) filled with `background` (default
        transparent), the document scaled to fill it: the pixels of `casteljau svg` with the same
        options (tolerance: --tolerance, flattening tolerance in pixels)."""
        bg = _color(background if background is not None else (0, 0, 0, 0))
        if tolerance is None:
            return Image(_handle=_out(_lib.casteljau_svg_render_image, self._h, width or 0, height or 0, zoom or 0.0, bg))
        w, h = self.output_size(width, height, zoom)
        iw, ih = self.intrinsic_size
        canvas = Canvas(w, h)
        canvas.clear((bg.r, bg.g, bg.b, bg.a))
        canvas.set_tolerance(tolerance)
        canvas.scale(w / iw, h / ih)
        self.render(canvas)
        return canvas.image


def render_svg(source: SvgSource, width: Optional[int] = None, height: Optional[int] = None,
               zoom: Optional[float] = None, background: Optional[Color] = None, *,
               tolerance: Optional[float] = None, **options) -> Image:
    """Renders an SVG file, its bytes or its text to a new Image: `casteljau svg` with -w, --height,
    -z, -b and --tolerance. The other keywords are SvgDocument's (resources, font_dir, font_file,
    skip_system_fonts, font_family, ..., dpi, export_id). The image has .to_png() and a numpy view
    (numpy.asarray(image): height x width x 4, premultiplied RGBA8)."""
    return SvgDocument(source, **options).render_image(width, height, zoom, background, tolerance)


def svg_to_png(src: SvgSource, dst: PathLike, width: Optional[int] = None, height: Optional[int] = None,
               zoom: Optional[float] = None, background: Optional[Color] = None, **options) -> None:
    """Renders an SVG file (or its bytes or text) to the PNG file `dst`, as
    `casteljau svg SRC -o DST` does with the same options (see render_svg)."""
    render_svg(src, width, height, zoom, background, **options).to_png(dst)
