"""The backend scene in Python (the ctypes binding in python/), the same as examples/scene.cpp
and examples/c/scene.c.  Usage: python3 scene.py OUT.png FONT.ttf"""
import sys

import casteljau as cj


def main(out, font_path):
    canvas = cj.Canvas(200, 120)
    canvas.clear((255, 255, 255))
    canvas.fill_rect(10, 10, 60, 40, cj.Paint((255, 0, 0)))
    canvas.fill_rect(80, 10, 110, 40, cj.Paint.linear((80, 0), (190, 0), [(0, (0, 0, 255)), (1, (0, 255, 0))]))
    canvas.save()
    canvas.clip(cj.Path().add_circle(50, 90, 25))
    canvas.fill_rect(0, 60, 200, 60, cj.Paint((255, 165, 0)))
    canvas.restore()
    canvas.stroke(cj.Path().move_to(90, 70).line_to(190, 70), cj.Stroke(width=4), cj.Paint((0, 0, 0)))
    checker = cj.Image(2, 2)
    px = checker.pixels()
    s = checker.stride
    for i, color in enumerate([(255, 0, 0, 255), (0, 255, 0, 255), (0, 0, 255, 255), (255, 255, 255, 255)]):
        o = (i // 2) * s + 4 * (i % 2)
        px[o:o + 4] = bytes(color)
    canvas.draw_image(checker, matrix=(10, 0, 0, 10, 170, 80), sampling="nearest")
    canvas.draw_text(cj.Font(font_path), "casteljau", 14, 90, 90, cj.Paint((40, 40, 40)))
    canvas.to_png(out)
    try:
        import numpy  # noqa: F401
    except ImportError:
        return
    a = canvas.array()  # no copy: writing through it changes the canvas
    assert a.shape == (120, 200, 4) and tuple(a[30, 40]) == (255, 0, 0, 255)


if __name__ == "__main__":
    if len(sys.argv) < 3:
        sys.exit("usage: scene.py OUT.png FONT.ttf")
    main(sys.argv[1], sys.argv[2])
