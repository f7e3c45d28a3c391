"""Paragraph layout (casteljau_text.h): TextLayout, with the options of `casteljau text` under the
same names (--line-height is line_height, --feature is feature, ...)."""
from __future__ import annotations

import ctypes as _c
import os
from typing import List, NamedTuple, Optional, Sequence, Tuple, Union

from . import (Canvas, Color, Font, Image, Paint, PathLike, _check, _color, _Color, _declare, _Handle, _key, _lib,
               _out, _text)

_vp, _d, _i, _P = _c.c_void_p, _c.c_double, _c.c_int, _c.POINTER


class _Line(_c.Structure):
    _fields_ = [("text", _c.POINTER(_c.c_char)), ("length", _c.c_size_t), ("x", _d), ("baseline", _d), ("width", _d),
                ("rtl", _i)]


_declare([
    ("casteljau_text_style_create", _vp, []),
    ("casteljau_text_style_destroy", None, [_vp]),
    ("casteljau_text_style_set_size", _i, [_vp, _d]),
    ("casteljau_text_style_set_line_height", _i, [_vp, _d]),
    ("casteljau_text_style_set_width", _i, [_vp, _d]),
    ("casteljau_text_style_set_align", _i, [_vp, _i]),
    ("casteljau_text_style_set_direction", _i, [_vp, _i]),
    ("casteljau_text_style_set_script", _i, [_vp, _c.c_char_p]),
    ("casteljau_text_style_set_language", _i, [_vp, _c.c_char_p]),
    ("casteljau_text_style_add_feature", _i, [_vp, _c.c_char_p]),
    ("casteljau_text_style_add_variation", _i, [_vp, _c.c_char_p]),
    ("casteljau_text_style_set_system_fonts", _i, [_vp, _i]),
    ("casteljau_text_style_set_palette", _i, [_vp, _i]),
    ("casteljau_text_layout_create", _i, [_c.c_char_p, _P(_vp), _c.c_size_t, _vp, _P(_vp)]),
    ("casteljau_text_layout_destroy", None, [_vp]),
    ("casteljau_text_layout_size", _i, [_vp, _P(_d), _P(_d)]),
    ("casteljau_text_layout_bounds", _i, [_vp, _P(_d), _P(_d), _P(_d), _P(_d)]),
    ("casteljau_text_layout_line_count", _c.c_size_t, [_vp]),
    ("casteljau_text_layout_line", _i, [_vp, _c.c_size_t, _P(_Line)]),
    ("casteljau_text_layout_draw", _i, [_vp, _vp, _d, _d, _vp]),
    ("casteljau_text_layout_render_image", _i, [_vp, _vp, _Color, _i, _P(_vp)]),
])

_ALIGN = {"start": 0, "left": 1, "center": 2, "right": 3}
_DIRECTION = {"auto": 0, "ltr": 1, "rtl": 2}
DEFAULT_FONT = "DejaVuSans.ttf"


class TextLine(NamedTuple):
    """One line of a layout: its text, the left end after alignment, the baseline's y, the advance
    width (trailing spaces excluded), and whether its paragraph runs right to left."""
    text: str
    x: float
    baseline: float
    width: float
    rtl: bool


def _loaded_library_dir() -> Optional[str]:
    """The folder of the libcasteljau this process loaded (from /proc/self/maps)."""
    try:
        with open("/proc/self/maps") as maps:
            for line in maps:
                path = line.split(None, 5)[-1].strip()
                if os.path.basename(path).startswith("libcasteljau.so"):
                    return os.path.dirname(path)
    except OSError:
        pass
    return None


def default_font_dirs() -> List[str]:
    """Where TextLayout looks for DejaVuSans.ttf when no font is given, as the `text` command does
    around its executable: $CASTELJAU_FONT_DIR, then around the loaded library LIB:
    LIB/../share/casteljau/fonts and LIB/../../share/casteljau/fonts (an install, with or without
    a multiarch library folder), LIB/../fonts and LIB/../../fonts (a build tree in the source
    tree)."""
    dirs = []
    if os.environ.get("CASTELJAU_FONT_DIR"):
        dirs.append(os.environ["CASTELJAU_FONT_DIR"])
    lib = _loaded_library_dir()
    if lib:
        dirs += [os.path.join(lib, "..", "share", "casteljau", "fonts"),
                 os.path.join(lib, "..", "..", "share", "casteljau", "fonts"), os.path.join(lib, "..", "fonts"),
                 os.path.join(lib, "..", "..", "fonts")]
    return [os.path.normpath(d) for d in dirs]


def _default_font() -> str:
    for d in default_font_dirs():
        path = os.path.join(d, DEFAULT_FONT)
        if os.path.isfile(path):
            return path
    raise FileNotFoundError("cannot find the default font %s (looked in: %s); pass font= or set CASTELJAU_FONT_DIR"
                            % (DEFAULT_FONT, ", ".join(default_font_dirs()) or "nowhere"))


def _fonts(font, face) -> List[Font]:
    fonts = font if isinstance(font, (list, tuple)) else [font]
    faces = list(face) if isinstance(face, (list, tuple)) else [face]
    if len(faces) > max(len(fonts), 1):
        raise ValueError("face: given %d times for %d font(s)" % (len(faces), max(len(fonts), 1)))
    out = []
    for i, f in enumerate(fonts or [None]):
        if isinstance(f, Font):
            out.append(f)
        else:
            out.append(Font(_default_font() if f is None else f, faces[i] if i < len(faces) else 0))
    return out


class _Style(_Handle):
    _destroy = _lib.casteljau_text_style_destroy

    def __init__(self, size, width, align, line_height, direction, script, language, feature, variation, system_fonts,
                 palette):
        self._h = _lib.casteljau_text_style_create()
        if not self._h:
            raise MemoryError("casteljau: out of memory")
        _check(_lib.casteljau_text_style_set_size(self._h, size))
        _check(_lib.casteljau_text_style_set_width(self._h, width or 0))
        _check(_lib.casteljau_text_style_set_align(self._h, _key(_ALIGN, align, "alignment")))
        _check(_lib.casteljau_text_style_set_line_height(self._h, line_height))
        _check(_lib.casteljau_text_style_set_direction(self._h, _key(_DIRECTION, direction, "direction")))
        _check(_lib.casteljau_text_style_set_script(self._h, _text(script)))
        _check(_lib.casteljau_text_style_set_language(self._h, _text(language)))
        for f in [feature] if isinstance(feature, str) else feature:
            _check(_lib.casteljau_text_style_add_feature(self._h, _text(f)))
        for v in [variation] if isinstance(variation, str) else variation:
            _check(_lib.casteljau_text_style_add_variation(self._h, _text(v)))
        _check(_lib.casteljau_text_style_set_system_fonts(self._h, 1 if system_fonts else 0))
        _check(_lib.casteljau_text_style_set_palette(self._h, palette))


class TextLayout(_Handle):
    """UTF-8 text shaped (HarfBuzz: kerning, ligatures, marks, right to left) and laid out as
    `casteljau text` does, read once and drawn any number of times.

    font: a font file, a Font, or a list of them (a fallback chain: each character from the first
    font that has it); default DejaVuSans.ttf (see default_font_dirs). face: the face index of a
    collection, one per font. size: pixels per em (--size, default 32). width: wrap lines at word
    boundaries to this many pixels (--width). align: "start", "left", "center", "right".
    line_height: the line advance as a multiple of the first font's line spacing. direction:
    "auto", "ltr", "rtl". script (ISO 15924, "Arab"), language (BCP 47, "ar"). feature: HarfBuzz
    feature strings ("kern=0", "smcp"); variation: axis settings ("wght=700"), one or a list.
    system_fonts: take a character cluster no font of the chain has from the system's fonts
    (fontconfig), as `casteljau text` does unless --no-system-fonts; off by default, as in the C
    and C++ libraries, so that the output depends on the given fonts alone. palette: the CPAL
    palette colour glyphs are drawn in (--palette; 0, the font's first, by default).
    Layout space: pixels, x right, y down, (0, 0) the top-left corner of the text box."""
    _destroy = _lib.casteljau_text_layout_destroy

    def __init__(self, text: str, font: Union[PathLike, Font, Sequence[Union[PathLike, Font]], None] = None, *,
                 face: Union[int, Sequence[int]] = (), size: float = 32, width: Optional[float] = None,
                 align: str = "start", line_height: float = 1.0, direction: str = "auto",
                 script: Optional[str] = None, language: Optional[str] = None,
                 feature: Union[str, Sequence[str]] = (), variation: Union[str, Sequence[str]] = (),
                 system_fonts: bool = False, palette: int = 0) -> None:
        style = _Style(size, width, align, line_height, direction, script, language, feature, variation, system_fonts,
                       palette)
        fonts = _fonts(font, face)
        handles = (_vp * len(fonts))(*[f._h for f in fonts])
        self._h = _out(_lib.casteljau_text_layout_create, text.encode("utf-8"), handles, len(fonts), style._h)

    def _box(self) -> Tuple[float, float]:
        w, h = _d(), _d()
        _check(_lib.casteljau_text_layout_size(self._h, _c.byref(w), _c.byref(h)))
        return (w.value, h.value)

    @property
    def width(self) -> float:
        """The text box's width: the wrap width, or the widest line without wrapping."""
        return self._box()[0]

    @property
    def height(self) -> float:
        """The text box's height: first ascender to last descender, line advances between."""
        return self._box()[1]

    @property
    def bounds(self) -> Tuple[float, float, float, float]:
        """The box united with the ink of every glyph: (x0, y0, x1, y1) in layout space."""
        v = [_d() for _ in range(4)]
        _check(_lib.casteljau_text_layout_bounds(self._h, *[_c.byref(x) for x in v]))
        return tuple(x.value for x in v)

    @property
    def lines(self) -> List[TextLine]:
        out = []
        for i in range(_lib.casteljau_text_layout_line_count(self._h)):
            line = _Line()
            _check(_lib.casteljau_text_layout_line(self._h, i, _c.byref(line)))
            text = _c.string_at(line.text, line.length).decode("utf-8")
            out.append(TextLine(text, line.x, line.baseline, line.width, bool(line.rtl)))
        return out

    def draw(self, canvas: Canvas, x: float = 0.0, y: float = 0.0, color: Color = "black",
             paint: Optional[Paint] = None) -> None:
        """Draws the layout with its box's top-left corner at (x, y) in the canvas's user space, in
        `paint` (or a solid `color`)."""
        p = paint if paint is not None else Paint(_rgba(color))
        _check(_lib.casteljau_text_layout_draw(self._h, canvas._h, x, y, p._h))

    def render(self, color: Color = "black", background: Color = "white", padding: int = 4,
               gamma_correct: bool = False) -> Image:
        """The image `casteljau text` writes: the bounds rounded out to whole pixels plus `padding`
        on every side, filled with `background`, the text in `color` (--gamma-correct blends in
        linear light)."""
        p = Paint(_rgba(color), gamma_correct=gamma_correct)
        return Image(_handle=_out(_lib.casteljau_text_layout_render_image, self._h, p._h, _color(background), padding))


def _rgba(color: Color) -> Tuple[int, int, int, int]:
    c = _color(color)
    return (c.r, c.g, c.b, c.a)
