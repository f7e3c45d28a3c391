"""casteljau: a 2D vector rasterizer with exact-area anti-aliasing (ctypes binding of the C API).

Objects mirror the C API (include/casteljau/casteljau.h) and the C++ Canvas: Path, Stroke, Paint,
Image, Font and Canvas. Coordinates: pixel space, x right, y down; a Canvas maps user space to
pixels by its current transform. Colours are (r, g, b) or (r, g, b, a) tuples of 0..255 (straight
alpha); images hold premultiplied RGBA8. Every failing call raises casteljau.Error.
Thread-safety: one object belongs to one thread at a time.
"""
import ctypes
import ctypes.util
import os

__all__ = ["Error", "Path", "Stroke", "Paint", "Image", "Font", "Canvas", "version", "BLEND_MODES",
           "set_thread_count", "thread_count", "limits", "set_limits", "reset_limits"]


def _load():
    candidates = []
    if os.environ.get("CASTELJAU_LIBRARY"):
        candidates.append(os.environ["CASTELJAU_LIBRARY"])
    found = ctypes.util.find_library("casteljau")
    if found:
        candidates.append(found)
    candidates += ["libcasteljau.so.0", "/usr/local/lib/libcasteljau.so.0"]
    errors = []
    for c in candidates:
        try:
            return ctypes.CDLL(c)
        except OSError as e:
            errors.append(str(e))
    raise ImportError("casteljau: cannot load libcasteljau.so.0 (set CASTELJAU_LIBRARY): " + "; ".join(errors))


_lib = _load()
_c = ctypes
_status = _c.c_int
_vp = _c.c_void_p
_d = _c.c_double


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
                ("input_bytes", _c.c_uint64)]


def _sig(name, restype, *argtypes):
    f = getattr(_lib, name)
    f.restype = restype
    f.argtypes = list(argtypes)
    return f


_P = _c.POINTER
for _name, _res, _args in [
    ("casteljau_version_string", _c.c_char_p, []),
    ("casteljau_last_error", _c.c_char_p, []),
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
    ("casteljau_image_create", _status, [_c.c_int, _c.c_int, _P(_vp)]),
    ("casteljau_image_read_png", _status, [_c.c_char_p, _P(_vp)]),
    ("casteljau_image_write_png", _status, [_vp, _c.c_char_p]),
    ("casteljau_image_destroy", None, [_vp]),
    ("casteljau_image_width", _c.c_int, [_vp]),
    ("casteljau_image_height", _c.c_int, [_vp]),
    ("casteljau_image_stride", _c.c_size_t, [_vp]),
    ("casteljau_image_data", _P(_c.c_uint8), [_vp]),
    ("casteljau_font_load", _status, [_c.c_char_p, _P(_vp)]),
    ("casteljau_font_destroy", None, [_vp]),
    ("casteljau_canvas_create", _status, [_vp, _P(_vp)]),
    ("casteljau_canvas_destroy", None, [_vp]),
    ("casteljau_canvas_save", _status, [_vp]),
    ("casteljau_canvas_restore", _status, [_vp]),
    ("casteljau_canvas_translate", _status, [_vp, _d, _d]),
    ("casteljau_canvas_scale", _status, [_vp, _d, _d]),
    ("casteljau_canvas_rotate", _status, [_vp, _d]),
    ("casteljau_canvas_concat", _status, [_vp, _P(_Matrix)]),
    ("casteljau_canvas_clip_rect", _status, [_vp, _d, _d, _d, _d]),
    ("casteljau_canvas_clip_path", _status, [_vp, _vp, _c.c_int]),
    ("casteljau_canvas_set_opacity", _status, [_vp, _d]),
    ("casteljau_canvas_set_blend_mode", _status, [_vp, _c.c_int]),
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
]:
    _sig(_name, _res, *_args)

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
    """A failed call: `status` is the C API's status code, the message is the library's."""

    def __init__(self, status, message):
        super().__init__(message)
        self.status = status


def _check(status):
    if status != 0:
        raise Error(status, _lib.casteljau_last_error().decode("utf-8", "replace"))


def _key(table, name, what):
    try:
        return table[name]
    except KeyError:
        raise ValueError("unknown %s %r (expected one of %s)" % (what, name, ", ".join(table))) from None


def _color(c):
    c = tuple(int(v) for v in c)
    return _Color(*(c + (255,) if len(c) == 3 else c))


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


def version():
    return _lib.casteljau_version_string().decode()


def set_thread_count(n):
    """Sizes the process-wide thread pool casteljau's parallel work shares (0: every core)."""
    _check(_lib.casteljau_set_thread_count(n))


def thread_count():
    return _lib.casteljau_thread_count()


def limits():
    """The process-wide resource limits in force, as a dict (README "Limits")."""
    lim = _Limits()
    _check(_lib.casteljau_limits_get(_c.byref(lim), _c.sizeof(lim)))
    return {name: getattr(lim, name) for name, _ in _Limits._fields_}


def set_limits(**fields):
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


def reset_limits():
    _lib.casteljau_limits_reset()


class _Handle:
    _destroy = None

    def __del__(self):
        h, self._h = getattr(self, "_h", None), None
        if h and self._destroy is not None:
            type(self)._destroy(h)


class Path(_Handle):
    """Contours of lines and curves in user space; methods return the path so they chain."""
    _destroy = _lib.casteljau_path_destroy

    def __init__(self, svg=None):
        self._h = _out(_lib.casteljau_path_from_svg, svg.encode()) if svg is not None else _lib.casteljau_path_create()
        if not self._h:
            raise MemoryError("casteljau: out of memory")

    def move_to(self, x, y):
        _check(_lib.casteljau_path_move_to(self._h, x, y)); return self

    def line_to(self, x, y):
        _check(_lib.casteljau_path_line_to(self._h, x, y)); return self

    def quad_to(self, cx, cy, x, y):
        _check(_lib.casteljau_path_quad_to(self._h, cx, cy, x, y)); return self

    def cubic_to(self, c1x, c1y, c2x, c2y, x, y):
        _check(_lib.casteljau_path_cubic_to(self._h, c1x, c1y, c2x, c2y, x, y)); return self

    def close(self):
        _check(_lib.casteljau_path_close(self._h)); return self

    def add_rect(self, x, y, w, h):
        _check(_lib.casteljau_path_add_rect(self._h, x, y, w, h)); return self

    def add_ellipse(self, cx, cy, rx, ry):
        _check(_lib.casteljau_path_add_ellipse(self._h, cx, cy, rx, ry)); return self

    def add_circle(self, cx, cy, r):
        return self.add_ellipse(cx, cy, r, r)


class Stroke(_Handle):
    """A stroke style: width, cap (butt, round, square), join (miter, miter-clip, round, bevel), dashes."""
    _destroy = _lib.casteljau_stroke_destroy

    def __init__(self, width=1.0, cap="butt", join="miter", miter_limit=4.0, dashes=(), dash_offset=0.0):
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
    """What a fill paints: Paint(color), Paint.linear(...), Paint.radial(...), Paint.image(...)."""
    _destroy = _lib.casteljau_paint_destroy

    def __init__(self, color=(0, 0, 0), opacity=1.0, blend="normal", _handle=None):
        self._h = _handle if _handle is not None else _out(_lib.casteljau_paint_create_solid, _color(color))
        if opacity != 1.0:
            _check(_lib.casteljau_paint_set_opacity(self._h, opacity))
        if blend != "normal":
            _check(_lib.casteljau_paint_set_blend_mode(self._h, _blend(blend)))

    @classmethod
    def linear(cls, p0, p1, stops, spread="pad", matrix=None, **kw):
        arr, n = _stops(stops)
        return cls(_handle=_out(_lib.casteljau_paint_create_linear, p0[0], p0[1], p1[0], p1[1], arr, n,
                                _key(_SPREAD, spread, "spread"), _matrix(matrix)), **kw)

    @classmethod
    def radial(cls, center, r, stops, focal=None, fr=0.0, spread="pad", matrix=None, **kw):
        f = focal if focal is not None else center
        arr, n = _stops(stops)
        return cls(_handle=_out(_lib.casteljau_paint_create_radial, center[0], center[1], r, f[0], f[1], fr, arr, n,
                                _key(_SPREAD, spread, "spread"), _matrix(matrix)), **kw)

    @classmethod
    def image(cls, image, sampling="bilinear", matrix=None, repeat=False, **kw):
        return cls(_handle=_out(_lib.casteljau_paint_create_image, image._h, _key(_SAMPLING, sampling, "sampling"),
                                _matrix(matrix), 1 if repeat else 0), **kw)


class Image(_Handle):
    """Premultiplied RGBA8 pixels: Image(width, height) (transparent) or Image.read_png(path)."""
    _destroy = _lib.casteljau_image_destroy

    def __init__(self, width=None, height=None, _handle=None):
        self._h = _handle if _handle is not None else _out(_lib.casteljau_image_create, int(width), int(height))

    @classmethod
    def read_png(cls, path):
        return cls(_handle=_out(_lib.casteljau_image_read_png, os.fsencode(path)))

    @property
    def width(self):
        return _lib.casteljau_image_width(self._h)

    @property
    def height(self):
        return _lib.casteljau_image_height(self._h)

    @property
    def stride(self):
        return _lib.casteljau_image_stride(self._h)

    def to_png(self, path):
        _check(_lib.casteljau_image_write_png(self._h, os.fsencode(path)))

    def pixels(self):
        """A writable memoryview of the pixels (height x stride bytes), valid while the image lives."""
        n = self.stride * self.height
        buf = (_c.c_uint8 * n).from_address(_c.addressof(_lib.casteljau_image_data(self._h).contents))
        buf._owner = self  # keeps the image alive as long as the view's buffer
        return memoryview(buf).cast("B")

    def array(self):
        """The pixels as a numpy array of shape (height, width, 4), uint8, sharing memory (no copy)."""
        import numpy as np
        flat = np.frombuffer(self.pixels(), dtype=np.uint8)
        return np.lib.stride_tricks.as_strided(flat, shape=(self.height, self.width, 4), strides=(self.stride, 4, 1))


class Font(_Handle):
    """A font file (TrueType, OpenType)."""
    _destroy = _lib.casteljau_font_destroy

    def __init__(self, path):
        self._h = _out(_lib.casteljau_font_load, os.fsencode(path))


class Canvas(_Handle):
    """Draws into its own Image (Canvas(width, height)) or into a given one (Canvas(image=...))."""
    _destroy = _lib.casteljau_canvas_destroy

    def __init__(self, width=None, height=None, image=None):
        self.image = image if image is not None else Image(width, height)
        self._h = _out(_lib.casteljau_canvas_create, self.image._h)

    width = property(lambda self: self.image.width)
    height = property(lambda self: self.image.height)
    stride = property(lambda self: self.image.stride)

    def save(self):
        _check(_lib.casteljau_canvas_save(self._h))

    def restore(self):
        _check(_lib.casteljau_canvas_restore(self._h))

    def translate(self, tx, ty):
        _check(_lib.casteljau_canvas_translate(self._h, tx, ty))

    def scale(self, sx, sy=None):
        _check(_lib.casteljau_canvas_scale(self._h, sx, sx if sy is None else sy))

    def rotate(self, radians):
        _check(_lib.casteljau_canvas_rotate(self._h, radians))

    def concat(self, matrix):
        _check(_lib.casteljau_canvas_concat(self._h, _matrix(matrix)))

    def clip_rect(self, x, y, w, h):
        _check(_lib.casteljau_canvas_clip_rect(self._h, x, y, w, h))

    def clip(self, path, rule="nonzero"):
        _check(_lib.casteljau_canvas_clip_path(self._h, path._h, _key(_RULE, rule, "fill rule")))

    def set_opacity(self, opacity):
        _check(_lib.casteljau_canvas_set_opacity(self._h, opacity))

    def set_blend_mode(self, mode):
        _check(_lib.casteljau_canvas_set_blend_mode(self._h, _blend(mode)))

    def clear(self, color=(0, 0, 0, 0)):
        _check(_lib.casteljau_canvas_clear(self._h, _color(color)))

    def fill(self, path, paint, rule="nonzero"):
        _check(_lib.casteljau_canvas_fill_path(self._h, path._h, paint._h, _key(_RULE, rule, "fill rule")))

    def fill_rect(self, x, y, w, h, paint):
        _check(_lib.casteljau_canvas_fill_rect(self._h, x, y, w, h, paint._h))

    def stroke(self, path, stroke, paint):
        _check(_lib.casteljau_canvas_stroke_path(self._h, path._h, stroke._h, paint._h))

    def draw_image(self, image, matrix=None, sampling="bilinear", opacity=1.0):
        _check(_lib.casteljau_canvas_draw_image(self._h, image._h, _matrix(matrix),
                                                _key(_SAMPLING, sampling, "sampling"), opacity))

    def draw_text(self, font, text, size, x, y, paint):
        _check(_lib.casteljau_canvas_draw_text(self._h, font._h, text.encode("utf-8"), size, x, y, paint._h))

    def begin_layer(self, opacity=1.0, blend="normal"):
        _check(_lib.casteljau_canvas_begin_layer(self._h, opacity, _blend(blend)))

    def end_layer(self):
        _check(_lib.casteljau_canvas_end_layer(self._h))

    def to_png(self, path):
        self.image.to_png(path)

    def pixels(self):
        return self.image.pixels()

    def array(self):
        return self.image.array()
