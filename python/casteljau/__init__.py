"""casteljau: a 2D vector rasterizer with exact-area anti-aliasing (ctypes binding of the C API).

The three jobs, each one call, with the keyword names of the command line's options:

    casteljau.svg_to_png("badge.svg", "badge.png", width=256, background="white")
    image = casteljau.render_svg("badge.svg", zoom=2)          # an Image: .to_png(), numpy view
    image = casteljau.render_map("countries.json", 1600, layer="countries",
                                 projection="+proj=robin", fill_by="name", stroke="#4a4a4a")
    casteljau.render_tiles("countries.json", "tiles/", "0-4", layer="countries")
    image = casteljau.TextLayout("Hello, world", size=48, width=300).render()

And a drawing backend mirroring the C API (include/casteljau/casteljau.h) and the C++ Canvas:
Path, Stroke, Paint, Image, Font and Canvas. Coordinates: pixel space, x right, y down; a Canvas
maps user space to pixels by its current transform. Colours are CSS strings ("crimson",
"#4a4a4a") or (r, g, b) / (r, g, b, a) tuples of 0..255 (straight alpha); images hold
premultiplied RGBA8. Every failing call raises casteljau.Error with the library's message.
Thread-safety: one object belongs to one thread at a time (SvgDocument and MapData may be
rendered from several threads at once).
"""
from __future__ import annotations

import ctypes
import ctypes.util
import os
from typing import Any, Optional, Sequence, Tuple, Union

__all__ = ["Error", "Path", "Stroke", "Paint", "Image", "Font", "Canvas", "version", "BLEND_MODES",
           "set_thread_count", "thread_count", "limits", "set_limits", "reset_limits", "parse_color",
           "SvgDocument", "svg_to_png", "render_svg", "MapData", "MapCache", "render_map", "render_tiles", "TextLayout",
           "TextLine"]

Color = Union[str, Sequence[int]]
Matrix = Sequence[float]
PathLike = Union[str, "os.PathLike[str]"]


def _library_candidates():
    """Where the shared library is looked for, in order: $CASTELJAU_LIBRARY; the build tree next to
    this package's source folder (REPO/build when the package is imported from REPO/python); the
    build tree recorded when the package was installed with pip from a source tree; the system's
    library search; /usr/local/lib."""
    candidates = []
    if os.environ.get("CASTELJAU_LIBRARY"):
        candidates.append(os.environ["CASTELJAU_LIBRARY"])
    here = os.path.dirname(os.path.abspath(__file__))
    candidates.append(os.path.join(here, "..", "..", "build", "libcasteljau.so.0"))
    try:
        from ._build_tree import LIBRARY as recorded
        candidates.append(recorded)
    except ImportError:
        pass
    found = ctypes.util.find_library("casteljau")
    if found:
        candidates.append(found)
    return candidates + ["libcasteljau.so.0", "/usr/local/lib/libcasteljau.so.0"]


def _load():
    errors = []
    for c in _library_candidates():
        if os.sep in c and not os.path.exists(c):
            errors.append(c + ": not there")
            continue
        try:
            return ctypes.CDLL(c)
        except OSError as e:
            errors.append(str(e))
    raise ImportError("casteljau: cannot load libcasteljau.so.0 (build it with cmake, install it, or set "
                      "CASTELJAU_LIBRARY): " + "; ".join(errors))


_lib = _load()
_c = ctypes
_status = _c.c_int
_vp = _c.c_void_p
_d = _c.c_double
_P = _c.POINTER


class _Matrix(_c.Structure):
    _fields_ = [(n, _c.c_double) for n in "abcdef"]


class _Color(_c.Structure):
    _fields_ = [(n, _c.c_uint8) for n in "rgba"]


class _Stop(_c.Structure):
    _fields_ = [("offset", _c.c_double), ("color", _Color)]


class _Limits(_c.Structure):  # casteljau_limits, field for field
    _fields_ = [("canvas_dimension", _c.c_int32), ("canvas_pixels", _c.c_int64), ("path_points", _c.c_uint64),
                ("flattened_segments", _c.c_uint64), ("nesting_depth", _c.c_int32), ("svg_elements", _c.c_uint64),
                ("svg_image_nesting", _c.c_int32), ("svgz_bytes", _c.c_uint64), ("css_rules", _c.c_uint64),
                ("svg_text_chars", _c.c_uint64), ("filter_pixels", _c.c_int64), ("filter_primitives", _c.c_uint64),
                ("map_positions", _c.c_uint64), ("dashes", _c.c_uint64), ("font_file_bytes", _c.c_uint64),
                ("png_chunk_bytes", _c.c_uint64), ("png_ancillary_chunks", _c.c_uint32),
                ("jpeg_working_memory", _c.c_uint64), ("canvas_save_depth", _c.c_uint64), ("text_bytes", _c.c_uint64),
                ("input_bytes", _c.c_uint64),
                ("exact_work", _c.c_uint64)]


def _declare(signatures):
    """Sets restype and argtypes of each (name, restype, argtypes) of the C API."""
    for name, restype, argtypes in signatures:
        f = getattr(_lib, name)
        f.restype = restype
        f.argtypes = list(argtypes)


_declare([
    ("casteljau_version_string", _c.c_char_p, []),
    ("casteljau_last_error", _c.c_char_p, []),
    ("casteljau_free", None, [_vp]),
    ("casteljau_color_parse", _status, [_c.c_char_p, _P(_Color)]),
    ("casteljau_path_create", _vp, []),
    ("casteljau_path_destroy", None, [_vp]),
    ("casteljau_path_from_svg", _status, [_c.c_char_p, _P(_vp)]),
    ("casteljau_path_move_to", _status, [_vp, _d, _d]),
    ("casteljau_path_line_to", _status, [_vp, _d, _d]),
    ("casteljau_path_quad_to", _status, [_vp, _d, _d, _d, _d]),
    ("casteljau_path_cubic_to", _status, [_vp, _d, _d, _d, _d, _d, _d]),
    ("casteljau_path_close", _status, [_vp]),
    ("casteljau_path_add_rect", _status, [_vp, _d, _d, _d, _d]),
    ("casteljau_path_add_ellipse", _status, [_vp, _d, _d, _d, _d]),
    ("casteljau_path_bounds", _status, [_vp, _P(_d), _P(_d), _P(_d), _P(_d)]),
    ("casteljau_stroke_create", _vp, []),
    ("casteljau_stroke_destroy", None, [_vp]),
    ("casteljau_stroke_set_width", _status, [_vp, _d]),
    ("casteljau_stroke_set_cap", _status, [_vp, _c.c_int]),
    ("casteljau_stroke_set_join", _status, [_vp, _c.c_int, _d]),
    ("casteljau_stroke_set_dashes", _status, [_vp, _P(_d), _c.c_size_t, _d]),
    ("casteljau_paint_create_solid", _status, [_Color, _P(_vp)]),
    ("casteljau_paint_create_linear", _status, [_d, _d, _d, _d, _P(_Stop), _c.c_size_t, _c.c_int, _P(_Matrix), _P(_vp)]),
    ("casteljau_paint_create_radial", _status,
     [_d, _d, _d, _d, _d, _d, _P(_Stop), _c.c_size_t, _c.c_int, _P(_Matrix), _P(_vp)]),
    ("casteljau_paint_create_image", _status, [_vp, _c.c_int, _P(_Matrix), _c.c_int, _P(_vp)]),
    ("casteljau_paint_destroy", None, [_vp]),
    ("casteljau_paint_set_opacity", _status, [_vp, _d]),
    ("casteljau_paint_set_blend_mode", _status, [_vp, _c.c_int]),
    ("casteljau_paint_set_linear_blend", _status, [_vp, _c.c_int]),
    ("casteljau_image_create", _status, [_c.c_int, _c.c_int, _P(_vp)]),
    ("casteljau_image_read_png", _status, [_c.c_char_p, _P(_vp)]),
    ("casteljau_image_decode_png", _status, [_c.c_char_p, _c.c_size_t, _P(_vp)]),
    ("casteljau_image_write_png", _status, [_vp, _c.c_char_p]),
    ("casteljau_image_encode_png", _status, [_vp, _P(_P(_c.c_uint8)), _P(_c.c_size_t)]),
    ("casteljau_image_destroy", None, [_vp]),
    ("casteljau_image_width", _c.c_int, [_vp]),
    ("casteljau_image_height", _c.c_int, [_vp]),
    ("casteljau_image_stride", _c.c_size_t, [_vp]),
    ("casteljau_image_data", _P(_c.c_uint8), [_vp]),
    ("casteljau_font_load", _status, [_c.c_char_p, _P(_vp)]),
    ("casteljau_font_load_face", _status, [_c.c_char_p, _c.c_int, _P(_vp)]),
    ("casteljau_font_destroy", None, [_vp]),
    ("casteljau_canvas_create", _status, [_vp, _P(_vp)]),
    ("casteljau_canvas_destroy", None, [_vp]),
    ("casteljau_canvas_save", _status, [_vp]),
    ("casteljau_canvas_restore", _status, [_vp]),
    ("casteljau_canvas_translate", _status, [_vp, _d, _d]),
    ("casteljau_canvas_scale", _status, [_vp, _d, _d]),
    ("casteljau_canvas_rotate", _status, [_vp, _d]),
    ("casteljau_canvas_concat", _status, [_vp, _P(_Matrix)]),
    ("casteljau_canvas_set_transform", _status, [_vp, _P(_Matrix)]),
    ("casteljau_canvas_get_transform", _status, [_vp, _P(_Matrix)]),
    ("casteljau_canvas_clip_rect", _status, [_vp, _d, _d, _d, _d]),
    ("casteljau_canvas_clip_path", _status, [_vp, _vp, _c.c_int]),
    ("casteljau_canvas_set_opacity", _status, [_vp, _d]),
    ("casteljau_canvas_set_blend_mode", _status, [_vp, _c.c_int]),
    ("casteljau_canvas_set_tolerance", _status, [_vp, _d]),
    ("casteljau_canvas_clear", _status, [_vp, _Color]),
    ("casteljau_canvas_fill_path", _status, [_vp, _vp, _vp, _c.c_int]),
    ("casteljau_canvas_fill_rect", _status, [_vp, _d, _d, _d, _d, _vp]),
    ("casteljau_canvas_stroke_path", _status, [_vp, _vp, _vp, _vp]),
    ("casteljau_canvas_draw_image", _status, [_vp, _vp, _P(_Matrix), _c.c_int, _d]),
    ("casteljau_canvas_draw_text", _status, [_vp, _vp, _c.c_char_p, _d, _d, _d, _vp]),
    ("casteljau_canvas_begin_layer", _status, [_vp, _d, _c.c_int]),
    ("casteljau_canvas_end_layer", _status, [_vp]),
    ("casteljau_limits_get", _status, [_P(_Limits), _c.c_size_t]),
    ("casteljau_limits_set", _status, [_P(_Limits), _c.c_size_t]),
    ("casteljau_limits_reset", None, []),
    ("casteljau_set_thread_count", _status, [_c.c_int]),
    ("casteljau_thread_count", _c.c_int, []),
])

BLEND_MODES = ["normal", "multiply", "screen", "overlay", "darken", "lighten", "color-dodge", "color-burn",
               "hard-light", "soft-light", "difference", "exclusion", "hue", "saturation", "color", "luminosity",
               "clear", "copy", "destination", "destination-over", "source-in", "destination-in", "source-out",
               "destination-out", "source-atop", "destination-atop", "xor", "plus-lighter"]
_SAMPLING = {"nearest": 0, "bilinear": 1, "bicubic": 2}
_SPREAD = {"pad": 0, "reflect": 1, "repeat": 2}
_RULE = {"nonzero": 0, "evenodd": 1}
_CAP = {"butt": 0, "round": 1, "square": 2}
_JOIN = {"miter": 0, "miter-clip": 1, "round": 2, "bevel": 3}


class Error(Exception):
    """A failed call: `status` is the C API's status code (casteljau_status), the message is the
    library's (casteljau_last_error)."""

    def __init__(self, status: int, message: str) -> None:
        super().__init__(message)
        self.status = status


def _check(status: int) -> None:
    if status != 0:
        raise Error(status, _lib.casteljau_last_error().decode("utf-8", "replace"))


def _key(table, name, what):
    try:
        return table[name]
    except KeyError:
        raise ValueError("unknown %s %r (expected one of %s)" % (what, name, ", ".join(table))) from None


def _color(c: Color) -> _Color:
    if isinstance(c, str):
        out = _Color()
        _check(_lib.casteljau_color_parse(c.encode("utf-8"), _c.byref(out)))
        return out
    c = tuple(int(v) for v in c)
    return _Color(*(c + (255,) if len(c) == 3 else c))


def parse_color(text: str) -> Tuple[int, int, int, int]:
    """A CSS colour ("crimson", "#4a4a4a", "rgb(10 20 30 / 50%)") as an (r, g, b, a) tuple."""
    c = _color(text)
    return (c.r, c.g, c.b, c.a)


def _matrix(m):
    return None if m is None else _c.byref(_Matrix(*[float(v) for v in m]))


def _out(create, *args):
    h = _vp()
    _check(create(*args, _c.byref(h)))
    return h


def _blend(name):
    if name not in BLEND_MODES:
        raise ValueError("unknown blend mode %r (expected one of %s)" % (name, ", ".join(BLEND_MODES)))
    return BLEND_MODES.index(name)


def _text(s: Optional[str]) -> Optional[bytes]:
    return None if s is None else s.encode("utf-8")


def version() -> str:
    return _lib.casteljau_version_string().decode()


def set_thread_count(n: int) -> None:
    """Sizes the process-wide thread pool casteljau's parallel work shares (0: every core)."""
    _check(_lib.casteljau_set_thread_count(n))


def thread_count() -> int:
    return _lib.casteljau_thread_count()


def limits() -> dict:
    """The process-wide resource limits in force, as a dict (README "Limits")."""
    lim = _Limits()
    _check(_lib.casteljau_limits_get(_c.byref(lim), _c.sizeof(lim)))
    return {name: getattr(lim, name) for name, _ in _Limits._fields_}


def set_limits(**fields: int) -> None:
    """Changes the named limits (the others keep their values); raises Error, changing nothing,
    for a value outside the limit's range and ValueError for an unknown name."""
    lim = _Limits()
    _check(_lib.casteljau_limits_get(_c.byref(lim), _c.sizeof(lim)))
    names = {name for name, _ in _Limits._fields_}
    for name, value in fields.items():
        if name not in names:
            raise ValueError("unknown limit %r (expected one of %s)" % (name, ", ".join(sorted(names))))
        setattr(lim, name, value)
    _check(_lib.casteljau_limits_set(_c.byref(lim), _c.sizeof(lim)))


def reset_limits() -> None:
    _lib.casteljau_limits_reset()


class _Handle:
    _destroy: Any = None
    _h: Any = None

    def __del__(self):
        h, self._h = getattr(self, "_h", None), None
        if h and self._destroy is not None:
            type(self)._destroy(h)


class Path(_Handle):
    """Contours of lines and curves in user space; methods return the path so they chain."""
    _destroy = _lib.casteljau_path_destroy

    def __init__(self, svg: Optional[str] = None) -> None:
        self._h = _out(_lib.casteljau_path_from_svg, svg.encode()) if svg is not None else _lib.casteljau_path_create()
        if not self._h:
            raise MemoryError("casteljau: out of memory")

    @classmethod
    def from_svg(cls, d: str) -> Path:
        """Parses SVG path data ("M10 10 L 20 20 Z"); a malformed one raises Error (status 2,
        the message names the position)."""
        return cls(d)

    def move_to(self, x: float, y: float) -> Path:
        _check(_lib.casteljau_path_move_to(self._h, x, y)); return self

    def line_to(self, x: float, y: float) -> Path:
        _check(_lib.casteljau_path_line_to(self._h, x, y)); return self

    def quad_to(self, cx: float, cy: float, x: float, y: float) -> Path:
        _check(_lib.casteljau_path_quad_to(self._h, cx, cy, x, y)); return self

    def cubic_to(self, c1x: float, c1y: float, c2x: float, c2y: float, x: float, y: float) -> Path:
        _check(_lib.casteljau_path_cubic_to(self._h, c1x, c1y, c2x, c2y, x, y)); return self

    def close(self) -> Path:
        _check(_lib.casteljau_path_close(self._h)); return self

    def add_rect(self, x: float, y: float, w: float, h: float) -> Path:
        _check(_lib.casteljau_path_add_rect(self._h, x, y, w, h)); return self

    def add_ellipse(self, cx: float, cy: float, rx: float, ry: float) -> Path:
        _check(_lib.casteljau_path_add_ellipse(self._h, cx, cy, rx, ry)); return self

    def add_circle(self, cx: float, cy: float, r: float) -> Path:
        return self.add_ellipse(cx, cy, r, r)

    def bounds(self) -> Tuple[float, float, float, float]:
        """The tight bounds (x0, y0, x1, y1); all zeros for an empty path."""
        v = [_d() for _ in range(4)]
        _check(_lib.casteljau_path_bounds(self._h, *[_c.byref(x) for x in v]))
        return tuple(x.value for x in v)


class Stroke(_Handle):
    """A stroke style: width, cap (butt, round, square), join (miter, miter-clip, round, bevel), dashes."""
    _destroy = _lib.casteljau_stroke_destroy

    def __init__(self, width: float = 1.0, cap: str = "butt", join: str = "miter", miter_limit: float = 4.0,
                 dashes: Sequence[float] = (), dash_offset: float = 0.0) -> None:
        self._h = _lib.casteljau_stroke_create()
        if not self._h:
            raise MemoryError("casteljau: out of memory")
        _check(_lib.casteljau_stroke_set_width(self._h, width))
        _check(_lib.casteljau_stroke_set_cap(self._h, _key(_CAP, cap, "line cap")))
        _check(_lib.casteljau_stroke_set_join(self._h, _key(_JOIN, join, "line join"), miter_limit))
        arr = (_c.c_double * len(dashes))(*dashes)
        _check(_lib.casteljau_stroke_set_dashes(self._h, arr, len(dashes), dash_offset))


def _stops(stops):
    arr = (_Stop * len(stops))(*[_Stop(float(o), _color(c)) for o, c in stops])
    return arr, len(stops)


class Paint(_Handle):
    """What a fill paints: Paint(color), Paint.linear(...), Paint.radial(...), Paint.image(...).
    `gamma_correct` blends solid colours with coverage in linear light (--gamma-correct)."""
    _destroy = _lib.casteljau_paint_destroy

    def __init__(self, color: Color = (0, 0, 0), opacity: float = 1.0, blend: str = "normal",
                 gamma_correct: bool = False, _handle: Any = None) -> None:
        self._h = _handle if _handle is not None else _out(_lib.casteljau_paint_create_solid, _color(color))
        if opacity != 1.0:
            _check(_lib.casteljau_paint_set_opacity(self._h, opacity))
        if blend != "normal":
            _check(_lib.casteljau_paint_set_blend_mode(self._h, _blend(blend)))
        if gamma_correct:
            _check(_lib.casteljau_paint_set_linear_blend(self._h, 1))

    @classmethod
    def linear(cls, p0: Sequence[float], p1: Sequence[float], stops: Sequence[Tuple[float, Color]],
               spread: str = "pad", matrix: Optional[Matrix] = None, **kw: Any) -> Paint:
        arr, n = _stops(stops)
        return cls(_handle=_out(_lib.casteljau_paint_create_linear, p0[0], p0[1], p1[0], p1[1], arr, n,
                                _key(_SPREAD, spread, "spread"), _matrix(matrix)), **kw)

    @classmethod
    def radial(cls, center: Sequence[float], r: float, stops: Sequence[Tuple[float, Color]],
               focal: Optional[Sequence[float]] = None, fr: float = 0.0, spread: str = "pad",
               matrix: Optional[Matrix] = None, **kw: Any) -> Paint:
        f = focal if focal is not None else center
        arr, n = _stops(stops)
        return cls(_handle=_out(_lib.casteljau_paint_create_radial, center[0], center[1], r, f[0], f[1], fr, arr, n,
                                _key(_SPREAD, spread, "spread"), _matrix(matrix)), **kw)

    @classmethod
    def image(cls, image: Image, sampling: str = "bilinear", matrix: Optional[Matrix] = None,
              repeat: bool = False, **kw: Any) -> Paint:
        return cls(_handle=_out(_lib.casteljau_paint_create_image, image._h, _key(_SAMPLING, sampling, "sampling"),
                                _matrix(matrix), 1 if repeat else 0), **kw)


class Image(_Handle):
    """Premultiplied RGBA8 pixels: Image(width, height) (transparent), Image.read_png(path) or
    Image.from_png(bytes). numpy.asarray(image) (or image.array()) is a (height, width, 4) uint8 view
    of the pixels, without a copy."""
    _destroy = _lib.casteljau_image_destroy

    def __init__(self, width: Optional[int] = None, height: Optional[int] = None, _handle: Any = None) -> None:
        self._h = _handle if _handle is not None else _out(_lib.casteljau_image_create, int(width), int(height))

    @classmethod
    def read_png(cls, path: PathLike) -> Image:
        return cls(_handle=_out(_lib.casteljau_image_read_png, os.fsencode(path)))

    @classmethod
    def from_png(cls, data: bytes) -> Image:
        """Decodes a PNG file's bytes."""
        data = bytes(data)
        return cls(_handle=_out(_lib.casteljau_image_decode_png, data, len(data)))

    @property
    def width(self) -> int:
        return _lib.casteljau_image_width(self._h)

    @property
    def height(self) -> int:
        return _lib.casteljau_image_height(self._h)

    @property
    def stride(self) -> int:
        return _lib.casteljau_image_stride(self._h)

    def to_png(self, path: Optional[PathLike] = None) -> Optional[bytes]:
        """Writes a PNG file (atomically: never a half-written file), or returns its bytes when no
        path is given."""
        if path is not None:
            _check(_lib.casteljau_image_write_png(self._h, os.fsencode(path)))
            return None
        data, size = _P(_c.c_uint8)(), _c.c_size_t()
        _check(_lib.casteljau_image_encode_png(self._h, _c.byref(data), _c.byref(size)))
        try:
            return _c.string_at(data, size.value)
        finally:
            _lib.casteljau_free(data)

    def pixels(self) -> memoryview:
        """A writable memoryview of the pixels (height x stride bytes), valid while the image lives."""
        n = self.stride * self.height
        buf = (_c.c_uint8 * n).from_address(_c.addressof(_lib.casteljau_image_data(self._h).contents))
        buf._owner = self  # keeps the image alive as long as the view's buffer
        return memoryview(buf).cast("B")

    @property
    def __array_interface__(self) -> dict:
        address = _c.addressof(_lib.casteljau_image_data(self._h).contents)
        return {"version": 3, "shape": (self.height, self.width, 4), "typestr": "|u1",
                "data": (address, False), "strides": (self.stride, 4, 1)}

    def array(self):
        """The pixels as a numpy array of shape (height, width, 4), uint8, sharing memory (no copy)."""
        import numpy as np
        return np.asarray(self)


class Font(_Handle):
    """A font file (TrueType, OpenType, a collection: `face` picks the face)."""
    _destroy = _lib.casteljau_font_destroy

    def __init__(self, path: PathLike, face: int = 0) -> None:
        self._h = _out(_lib.casteljau_font_load_face, os.fsencode(path), face)


class Canvas(_Handle):
    """Draws into its own Image (Canvas(width, height)) or into a given one (Canvas(image=...))."""
    _destroy = _lib.casteljau_canvas_destroy

    def __init__(self, width: Optional[int] = None, height: Optional[int] = None, image: Optional[Image] = None) -> None:
        self.image = image if image is not None else Image(width, height)
        self._h = _out(_lib.casteljau_canvas_create, self.image._h)

    width = property(lambda self: self.image.width)
    height = property(lambda self: self.image.height)
    stride = property(lambda self: self.image.stride)

    def save(self) -> None:
        _check(_lib.casteljau_canvas_save(self._h))

    def restore(self) -> None:
        _check(_lib.casteljau_canvas_restore(self._h))

    def translate(self, tx: float, ty: float) -> None:
        _check(_lib.casteljau_canvas_translate(self._h, tx, ty))

    def scale(self, sx: float, sy: Optional[float] = None) -> None:
        _check(_lib.casteljau_canvas_scale(self._h, sx, sx if sy is None else sy))

    def rotate(self, radians: float) -> None:
        _check(_lib.casteljau_canvas_rotate(self._h, radians))

    def concat(self, matrix: Matrix) -> None:
        _check(_lib.casteljau_canvas_concat(self._h, _matrix(matrix)))

    @property
    def transform(self) -> Tuple[float, float, float, float, float, float]:
        """The current transform (a, b, c, d, e, f): x' = a x + c y + e, y' = b x + d y + f."""
        m = _Matrix()
        _check(_lib.casteljau_canvas_get_transform(self._h, _c.byref(m)))
        return (m.a, m.b, m.c, m.d, m.e, m.f)

    @transform.setter
    def transform(self, matrix: Matrix) -> None:
        _check(_lib.casteljau_canvas_set_transform(self._h, _matrix(matrix)))

    def clip_rect(self, x: float, y: float, w: float, h: float) -> None:
        _check(_lib.casteljau_canvas_clip_rect(self._h, x, y, w, h))

    def clip(self, path: Path, rule: str = "nonzero") -> None:
        _check(_lib.casteljau_canvas_clip_path(self._h, path._h, _key(_RULE, rule, "fill rule")))

    def set_opacity(self, opacity: float) -> None:
        _check(_lib.casteljau_canvas_set_opacity(self._h, opacity))

    def set_blend_mode(self, mode: str) -> None:
        _check(_lib.casteljau_canvas_set_blend_mode(self._h, _blend(mode)))

    def set_tolerance(self, tolerance: float) -> None:
        """Flattening tolerance in pixels (default 0.015; 1e-4 .. 10) of what is drawn next."""
        _check(_lib.casteljau_canvas_set_tolerance(self._h, tolerance))

    def clear(self, color: Color = (0, 0, 0, 0)) -> None:
        _check(_lib.casteljau_canvas_clear(self._h, _color(color)))

    def fill(self, path: Path, paint: Paint, rule: str = "nonzero") -> None:
        _check(_lib.casteljau_canvas_fill_path(self._h, path._h, paint._h, _key(_RULE, rule, "fill rule")))

    def fill_rect(self, x: float, y: float, w: float, h: float, paint: Paint) -> None:
        _check(_lib.casteljau_canvas_fill_rect(self._h, x, y, w, h, paint._h))

    def stroke(self, path: Path, stroke: Stroke, paint: Paint) -> None:
        _check(_lib.casteljau_canvas_stroke_path(self._h, path._h, stroke._h, paint._h))

    def draw_image(self, image: Image, matrix: Optional[Matrix] = None, sampling: str = "bilinear",
                   opacity: float = 1.0) -> None:
        _check(_lib.casteljau_canvas_draw_image(self._h, image._h, _matrix(matrix),
                                                _key(_SAMPLING, sampling, "sampling"), opacity))

    def draw_text(self, font: Font, text: str, size: float, x: float, y: float, paint: Paint) -> None:
        _check(_lib.casteljau_canvas_draw_text(self._h, font._h, text.encode("utf-8"), size, x, y, paint._h))

    def begin_layer(self, opacity: float = 1.0, blend: str = "normal") -> None:
        _check(_lib.casteljau_canvas_begin_layer(self._h, opacity, _blend(blend)))

    def end_layer(self) -> None:
        _check(_lib.casteljau_canvas_end_layer(self._h))

    def to_png(self, path: Optional[PathLike] = None) -> Optional[bytes]:
        return self.image.to_png(path)

    def pixels(self) -> memoryview:
        return self.image.pixels()

    def array(self):
        return self.image.array()


from ._svg import SvgDocument, render_svg, svg_to_png  # noqa: E402
from ._map import MapCache, MapData, render_map, render_tiles  # noqa: E402
from ._text import TextLayout, TextLine  # noqa: E402
