"""Maps and tile pyramids (casteljau_map.h): MapData, render_map and render_tiles, with the options
of `casteljau map` and `casteljau tiles` under the same names (--fill-by is fill_by,
--no-exact-overlaps is no_exact_overlaps, ...)."""
from __future__ import annotations

import ctypes as _c
import os
from typing import Any, Callable, Dict, Optional, Sequence, Tuple, Union

from . import (Canvas, Color, Image, PathLike, _check, _color, _Color, _declare, _Handle, _key, _lib, _out,
               _text, _JOIN, _CAP)

_vp, _d, _i, _P = _c.c_void_p, _c.c_double, _c.c_int, _c.POINTER


class _TileStats(_c.Structure):
    _fields_ = [("metatiles", _c.c_uint64), ("written", _c.c_uint64), ("skipped_empty", _c.c_uint64),
                ("skipped_existing", _c.c_uint64)]


_PROGRESS = _c.CFUNCTYPE(_c.c_int, _c.c_uint64, _c.c_uint64, _vp)

_declare([
    ("casteljau_map_load", _i, [_c.c_char_p, _c.c_char_p, _P(_vp)]),
    ("casteljau_map_parse", _i, [_c.c_char_p, _c.c_size_t, _c.c_char_p, _P(_vp)]),
    ("casteljau_map_destroy", None, [_vp]),
    ("casteljau_map_feature_count", _c.c_size_t, [_vp]),
    ("casteljau_map_style_create", _vp, []),
    ("casteljau_map_style_load", _i, [_c.c_char_p, _P(_vp)]),
    ("casteljau_map_style_destroy", None, [_vp]),
    ("casteljau_map_style_set_fill", _i, [_vp, _P(_Color)]),
    ("casteljau_map_style_set_stroke", _i, [_vp, _P(_Color)]),
    ("casteljau_map_style_set_stroke_width", _i, [_vp, _d]),
    ("casteljau_map_style_set_opacity", _i, [_vp, _d]),
    ("casteljau_map_style_set_fill_by", _i, [_vp, _c.c_char_p]),
    ("casteljau_map_style_set_ramp", _i, [_vp, _d, _Color, _d, _Color]),
    ("casteljau_map_style_set_background", _i, [_vp, _Color]),
    ("casteljau_map_style_set_line_join", _i, [_vp, _i]),
    ("casteljau_map_style_set_line_cap", _i, [_vp, _i]),
    ("casteljau_map_style_set_point_radius", _i, [_vp, _d]),
    ("casteljau_map_options_create", _vp, []),
    ("casteljau_map_options_destroy", None, [_vp]),
    ("casteljau_map_options_set_size", _i, [_vp, _i, _i]),
    ("casteljau_map_options_set_projection", _i, [_vp, _c.c_char_p]),
    ("casteljau_map_options_set_bbox", _i, [_vp, _d, _d, _d, _d]),
    ("casteljau_map_options_set_padding", _i, [_vp, _d]),
    ("casteljau_map_options_set_separate", _i, [_vp, _i]),
    ("casteljau_map_options_set_exact_overlaps", _i, [_vp, _i]),
    ("casteljau_map_options_set_tolerance", _i, [_vp, _d]),
    ("casteljau_map_cache_create", _vp, []),
    ("casteljau_map_cache_destroy", None, [_vp]),
    ("casteljau_map_options_set_cache", _i, [_vp, _vp]),
    ("casteljau_map_render_image", _i, [_vp, _vp, _vp, _P(_vp)]),
    ("casteljau_map_render", _i, [_vp, _vp, _vp, _vp]),
    ("casteljau_tile_options_create", _vp, []),
    ("casteljau_tile_options_destroy", None, [_vp]),
    ("casteljau_tile_options_set_zoom", _i, [_vp, _i, _i]),
    ("casteljau_tile_options_set_tile_size", _i, [_vp, _i, _i]),
    ("casteljau_tile_options_set_metatile", _i, [_vp, _i]),
    ("casteljau_tile_options_set_buffer", _i, [_vp, _i]),
    ("casteljau_tile_options_set_skip_empty", _i, [_vp, _i]),
    ("casteljau_tile_options_set_resume", _i, [_vp, _i]),
    ("casteljau_tile_options_set_shard", _i, [_vp, _i, _i]),
    ("casteljau_tile_options_set_name", _i, [_vp, _c.c_char_p]),
    ("casteljau_tile_options_set_separate", _i, [_vp, _i]),
    ("casteljau_tile_options_set_exact_overlaps", _i, [_vp, _i]),
    ("casteljau_tile_options_set_tolerance", _i, [_vp, _d]),
    ("casteljau_map_render_tiles", _i, [_vp, _vp, _vp, _c.c_char_p, _PROGRESS, _vp, _P(_TileStats)]),
])

_CANCELLED = 9
MapSource = Union["MapData", bytes, bytearray, memoryview, PathLike]
Progress = Callable[[int, int], Optional[bool]]
# The style options of `casteljau map` and `casteljau tiles` (their defaults there) that a style
# file replaces.
_COLOUR_OPTIONS = ("fill", "stroke", "stroke_width", "fill_by", "ramp", "point_radius", "opacity")


class MapData(_Handle):
    """Map data read once from GeoJSON, GeoJSON lines or TopoJSON, drawn any number of times (from
    several threads at once if need be).

    `source` is a file path (the reader chosen by its extension: .geojsonl/.ndjson GeoJSON lines,
    .topojson TopoJSON, else by content), the file's bytes, or JSON text (a str starting with "{"
    or "["). `layer` selects one object of a TopoJSON topology (--layer; default: all). Raises
    Error naming the JSON path of bad data."""
    _destroy = _lib.casteljau_map_destroy

    def __init__(self, source: Union[bytes, bytearray, memoryview, PathLike], layer: Optional[str] = None) -> None:
        if isinstance(source, (bytes, bytearray, memoryview)) or (
                isinstance(source, str) and source.lstrip()[:1] in ("{", "[")):
            data = source.encode("utf-8") if isinstance(source, str) else bytes(source)
            self._h = _out(_lib.casteljau_map_parse, data, len(data), _text(layer))
        else:
            self._h = _out(_lib.casteljau_map_load, os.fsencode(source), _text(layer))

    def __len__(self) -> int:
        """The number of features."""
        return _lib.casteljau_map_feature_count(self._h)


class MapCache(_Handle):
    """What one render learns about a MapData, kept for the next renders of it in any frame (a
    server or a viewer drawing one map again): where each feature's fill may overlap itself, so
    that the exact overlap check looks only there, and the data simplified to each of the last four
    scales drawn. Pass it to render_map(data, ..., cache=...) with the same MapData object and
    projection every time (another raises Error or ValueError). The pixels are those of a render
    without it, to rounding; the first render pays for the analysis (1.3 to 1.8 times as long),
    later ones draw faster. Threads drawing the same map may share one."""
    _destroy = _lib.casteljau_map_cache_destroy

    def __init__(self) -> None:
        self._h = _lib.casteljau_map_cache_create()
        if not self._h:
            raise MemoryError("casteljau: out of memory")
        self._data: Optional[MapData] = None  # the map it serves, kept alive as long as the cache


def _map_data(source: MapSource, layer: Optional[str]) -> MapData:
    if isinstance(source, MapData):
        if layer is not None:
            raise ValueError("layer selects a TopoJSON object when the map is read; this MapData is read already")
        return source
    return MapData(source, layer)


def _ramp(ramp) -> Tuple[float, _Color, float, _Color]:
    """--ramp MIN:COLOR,MAX:COLOR, or ((MIN, COLOR), (MAX, COLOR))."""
    if isinstance(ramp, str):
        parts, depth, cur = [], 0, ""
        for ch in ramp:  # colours may hold commas inside rgb(...): split at the top level
            depth += (ch == "(") - (ch == ")")
            if ch == "," and depth == 0:
                parts.append(cur)
                cur = ""
            else:
                cur += ch
        parts.append(cur)
        if len(parts) != 2 or any(":" not in p for p in parts):
            raise ValueError("ramp: expected MIN:COLOR,MAX:COLOR, got %r" % ramp)
        ramp = [(float(p[:p.index(":")]), p[p.index(":") + 1:]) for p in parts]
    (lo, lo_color), (hi, hi_color) = ramp
    return float(lo), _color(lo_color), float(hi), _color(hi_color)


class _Style(_Handle):
    """casteljau_map_style from the command line's style options, as build_map_style makes it."""
    _destroy = _lib.casteljau_map_style_destroy

    def __init__(self, style=None, fill="black", stroke=None, stroke_width=1.0, line_join="round", line_cap="round",
                 background="transparent", fill_by=None, ramp=None, point_radius=3.0, opacity=1.0, given=()):
        if style is not None:
            clash = [name for name in _COLOUR_OPTIONS if name in given]
            if clash:
                raise ValueError("style replaces the colour options; drop %s" % ", ".join(clash))
            self._h = _out(_lib.casteljau_map_style_load, os.fsencode(style))
            if background not in (None, "transparent"):
                _check(_lib.casteljau_map_style_set_background(self._h, _color(background)))
        else:
            self._h = _lib.casteljau_map_style_create()
            if not self._h:
                raise MemoryError("casteljau: out of memory")
            if ramp is not None and not fill_by:
                raise ValueError("ramp needs fill_by")
            _check(_lib.casteljau_map_style_set_fill(self._h, _optional_color(fill)))
            _check(_lib.casteljau_map_style_set_stroke(self._h, _optional_color(stroke)))
            _check(_lib.casteljau_map_style_set_stroke_width(self._h, stroke_width))
            _check(_lib.casteljau_map_style_set_opacity(self._h, opacity))
            _check(_lib.casteljau_map_style_set_fill_by(self._h, _text(fill_by)))
            if ramp is not None:
                _check(_lib.casteljau_map_style_set_ramp(self._h, *_ramp(ramp)))
            _check(_lib.casteljau_map_style_set_background(self._h, _color(background)))
            _check(_lib.casteljau_map_style_set_point_radius(self._h, point_radius))
        _check(_lib.casteljau_map_style_set_line_join(self._h, _key(_JOIN, line_join, "line join")))
        _check(_lib.casteljau_map_style_set_line_cap(self._h, _key(_CAP, line_cap, "line cap")))


def _optional_color(c):
    return None if c is None or c == "none" else _c.byref(_color(c))


def _style(kw: Dict[str, Any]) -> _Style:
    given = {k for k, v in kw.items() if v is not None}
    return _Style(given=given, **{k: v for k, v in kw.items() if v is not None})


def _bbox(bbox) -> Tuple[float, float, float, float]:
    """--bbox W,S,E,N, or a (west, south, east, north) sequence."""
    if isinstance(bbox, str):
        bbox = bbox.replace(",", " ").split()
    if len(bbox) != 4:
        raise ValueError("bbox: expected W,S,E,N in degrees, got %r" % (bbox,))
    return tuple(float(v) for v in bbox)


class _Options(_Handle):
    _destroy = _lib.casteljau_map_options_destroy

    def __init__(self, width, height, projection, bbox, padding, separate, no_exact_overlaps, tolerance):
        self._h = _lib.casteljau_map_options_create()
        if not self._h:
            raise MemoryError("casteljau: out of memory")
        if width is not None:
            _check(_lib.casteljau_map_options_set_size(self._h, width, height or 0))
        if projection is not None:
            _check(_lib.casteljau_map_options_set_projection(self._h, _text(projection)))
        if bbox is not None:
            _check(_lib.casteljau_map_options_set_bbox(self._h, *_bbox(bbox)))
        _check(_lib.casteljau_map_options_set_padding(self._h, padding))
        _check(_lib.casteljau_map_options_set_separate(self._h, 1 if separate else 0))
        _check(_lib.casteljau_map_options_set_exact_overlaps(self._h, 0 if no_exact_overlaps else 1))
        if tolerance is not None:
            _check(_lib.casteljau_map_options_set_tolerance(self._h, tolerance))


def render_map(source: MapSource, width: Optional[int] = None, height: Optional[int] = None, *,
               layer: Optional[str] = None, projection: str = "equirectangular",
               bbox: Union[str, Sequence[float], None] = None, padding: float = 0.0, fill: Optional[Color] = None,
               stroke: Optional[Color] = None, stroke_width: Optional[float] = None, line_join: str = "round",
               line_cap: str = "round", background: Optional[Color] = None, fill_by: Optional[str] = None,
               ramp: Union[str, Sequence[Tuple[float, Color]], None] = None, point_radius: Optional[float] = None,
               opacity: Optional[float] = None, style: Optional[PathLike] = None, separate: bool = False,
               no_exact_overlaps: bool = False, tolerance: Optional[float] = None,
               canvas: Optional[Canvas] = None, cache: Optional[MapCache] = None) -> Image:
    """Renders a map to a new Image: `casteljau map` with the same options, the same pixels.

    width (required without a canvas) and height (default: from the extent's aspect ratio) in
    pixels; projection: "equirectangular", "mercator", a PROJ string ("+proj=robin") or a CRS
    ("EPSG:3035"); bbox: "W,S,E,N" or (west, south, east, north) degrees mapped exactly onto the
    image; padding in pixels around the data's extent. Style: fill (a colour or "none"), stroke,
    stroke_width, line_join, line_cap, background, fill_by (a property picking each feature's
    colour from a palette, or from ramp: "MIN:COLOR,MAX:COLOR" or ((min, colour), (max, colour))),
    point_radius, opacity; or style, a JSON style file, which replaces the colour options (a
    background other than transparent still applies). separate: each fill on its own (seams);
    no_exact_overlaps: faster fills, exact for valid polygons; tolerance: flattening tolerance in
    pixels. With `canvas`, the map (of the canvas's size unless width is given) is drawn onto it
    under its transform and the canvas's image is returned. cache: a MapCache kept across the
    renders of one MapData object (see MapCache)."""
    data = _map_data(source, layer)
    if cache is not None:
        if cache._data is None and not isinstance(source, MapData):
            raise ValueError("a MapCache serves a MapData object: read the map once with MapData(...)")
        if cache._data is not None and cache._data is not data:
            raise ValueError("a MapCache serves the MapData it was first used with")
    st = _style(dict(style=style, fill=fill, stroke=stroke, stroke_width=stroke_width, line_join=line_join,
                     line_cap=line_cap, background=background, fill_by=fill_by, ramp=ramp,
                     point_radius=point_radius, opacity=opacity))
    if width is None and canvas is None:
        raise ValueError("render_map needs a width (or a canvas)")
    opts = _Options(width, height, projection, bbox, padding, separate, no_exact_overlaps, tolerance)
    if cache is not None:
        _check(_lib.casteljau_map_options_set_cache(opts._h, cache._h))
        cache._data = data
    if canvas is not None:
        _check(_lib.casteljau_map_render(data._h, st._h, opts._h, canvas._h))
        return canvas.image
    return Image(_handle=_out(_lib.casteljau_map_render_image, data._h, st._h, opts._h))


def _zoom(zoom) -> Tuple[int, int]:
    """--zoom MIN-MAX or one level; or an int; or (min, max)."""
    if isinstance(zoom, int):
        return zoom, zoom
    if isinstance(zoom, str):
        lo, _, hi = zoom.partition("-")
        return int(lo), int(hi or lo)
    lo, hi = zoom
    return int(lo), int(hi)


def _shard(shard) -> Tuple[int, int]:
    """--shard I/N, or (i, n)."""
    if isinstance(shard, str):
        i, _, n = shard.partition("/")
        return int(i), int(n)
    i, n = shard
    return int(i), int(n)


class _TileOptions(_Handle):
    _destroy = _lib.casteljau_tile_options_destroy

    def __init__(self, zoom, tile_size, scale, metatile, buffer, skip_empty, resume, shard, name, separate,
                 no_exact_overlaps, tolerance):
        self._h = _lib.casteljau_tile_options_create()
        if not self._h:
            raise MemoryError("casteljau: out of memory")
        _check(_lib.casteljau_tile_options_set_zoom(self._h, *_zoom(zoom)))
        _check(_lib.casteljau_tile_options_set_tile_size(self._h, tile_size, scale))
        _check(_lib.casteljau_tile_options_set_metatile(self._h, metatile))
        _check(_lib.casteljau_tile_options_set_buffer(self._h, buffer))
        _check(_lib.casteljau_tile_options_set_skip_empty(self._h, 1 if skip_empty else 0))
        _check(_lib.casteljau_tile_options_set_resume(self._h, 1 if resume else 0))
        if shard is not None:
            _check(_lib.casteljau_tile_options_set_shard(self._h, *_shard(shard)))
        _check(_lib.casteljau_tile_options_set_name(self._h, _text(name)))
        _check(_lib.casteljau_tile_options_set_separate(self._h, 1 if separate else 0))
        _check(_lib.casteljau_tile_options_set_exact_overlaps(self._h, 0 if no_exact_overlaps else 1))
        if tolerance is not None:
            _check(_lib.casteljau_tile_options_set_tolerance(self._h, tolerance))


def render_tiles(source: MapSource, output: PathLike, zoom: Union[int, str, Tuple[int, int]], *,
                 layer: Optional[str] = None, tile_size: int = 256, scale: int = 1, metatile: int = 8,
                 buffer: int = 64, skip_empty: bool = False, resume: bool = False,
                 shard: Union[str, Tuple[int, int], None] = None, name: str = "casteljau",
                 progress: Optional[Progress] = None, fill: Optional[Color] = None, stroke: Optional[Color] = None,
                 stroke_width: Optional[float] = None, line_join: str = "round", line_cap: str = "round",
                 background: Optional[Color] = None, fill_by: Optional[str] = None,
                 ramp: Union[str, Sequence[Tuple[float, Color]], None] = None, point_radius: Optional[float] = None,
                 opacity: Optional[float] = None, style: Optional[PathLike] = None, separate: bool = False,
                 no_exact_overlaps: bool = False, tolerance: Optional[float] = None) -> Dict[str, int]:
    """Renders a Web Mercator tile pyramid: `casteljau tiles SOURCE -o OUTPUT --zoom ZOOM` with the
    same options, the same tiles. `output` is a folder (OUTPUT/z/x/y.png) or a FILE.mbtiles; zoom
    is "MIN-MAX", one level, or (min, max), 0 to 24; shard "I/N" or (i, n). The style keywords
    are render_map's. progress(done, total) is called after each metatile (from a worker thread);
    returning False stops the pyramid (Error with status 9, "cancelled"), and an exception it
    raises stops it and is raised here. Returns the counts: metatiles, written, skipped_empty,
    skipped_existing."""
    data = _map_data(source, layer)
    st = _style(dict(style=style, fill=fill, stroke=stroke, stroke_width=stroke_width, line_join=line_join,
                     line_cap=line_cap, background=background, fill_by=fill_by, ramp=ramp,
                     point_radius=point_radius, opacity=opacity))
    opts = _TileOptions(zoom, tile_size, scale, metatile, buffer, skip_empty, resume, shard, name, separate,
                        no_exact_overlaps, tolerance)
    raised = []

    def report(done, total, _user):
        try:
            return 1 if progress(done, total) is False else 0
        except BaseException as e:  # noqa: B902 - handed to the caller below
            raised.append(e)
            return 1

    callback = _PROGRESS(report) if progress is not None else _PROGRESS()
    stats = _TileStats()
    status = _lib.casteljau_map_render_tiles(data._h, st._h, opts._h, os.fsencode(output), callback, None,
                                             _c.byref(stats))
    if status == _CANCELLED and raised:
        raise raised[0]
    _check(status)
    return {name: getattr(stats, name) for name, _ in _TileStats._fields_}
