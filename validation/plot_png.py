#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Writes one plot of an e2d-validate report as a PNG (for the README).

    python3 validation/plot_png.py report/validation/report.html "joints: speed against error" \
        validation/report-joints.png

The report's plots are inline SVG; the first whose title starts with the given text is
rendered with librsvg and cairo (Debian librsvg2-2 and libcairo2, loaded with ctypes: no
Python package needed), on white, at twice its size.
"""
import ctypes
import ctypes.util
import re
import sys


def find_svg(html, title):
    for match in re.finditer(r"<svg\b.*?</svg>", html, re.S):
        svg = match.group(0)
        if re.search(r"<text[^>]*>" + re.escape(title), svg):
            return svg
    return None


def load(name, fallback):
    path = ctypes.util.find_library(name) or fallback
    try:
        return ctypes.CDLL(path)
    except OSError:
        sys.exit(f"plot_png.py: cannot load {path} (Debian: apt-get install {fallback.split('.so')[0]}*)")


def render(svg, out, scale=2.0):
    rsvg = load("rsvg-2", "librsvg-2.so.2")
    cairo = load("cairo", "libcairo.so.2")
    rsvg.rsvg_handle_new_from_data.restype = ctypes.c_void_p
    rsvg.rsvg_handle_new_from_data.argtypes = [ctypes.c_char_p, ctypes.c_size_t, ctypes.c_void_p]
    rsvg.rsvg_handle_render_cairo.argtypes = [ctypes.c_void_p, ctypes.c_void_p]
    cairo.cairo_image_surface_create.restype = ctypes.c_void_p
    cairo.cairo_create.restype = ctypes.c_void_p
    cairo.cairo_create.argtypes = [ctypes.c_void_p]
    cairo.cairo_scale.argtypes = [ctypes.c_void_p, ctypes.c_double, ctypes.c_double]
    cairo.cairo_set_source_rgb.argtypes = [ctypes.c_void_p, ctypes.c_double, ctypes.c_double, ctypes.c_double]
    cairo.cairo_paint.argtypes = [ctypes.c_void_p]
    cairo.cairo_surface_write_to_png.argtypes = [ctypes.c_void_p, ctypes.c_char_p]
    cairo.cairo_surface_write_to_png.restype = ctypes.c_int
    cairo.cairo_destroy.argtypes = [ctypes.c_void_p]
    cairo.cairo_surface_destroy.argtypes = [ctypes.c_void_p]

    size = re.search(r'<svg[^>]*\bwidth="([\d.]+)"[^>]*\bheight="([\d.]+)"', svg)
    if not size:
        sys.exit("plot_png.py: the plot has no width and height")
    width, height = float(size.group(1)), float(size.group(2))
    if "xmlns=" not in svg[:200]:
        svg = svg.replace("<svg", '<svg xmlns="http://www.w3.org/2000/svg"', 1)
    data = svg.encode()
    handle = rsvg.rsvg_handle_new_from_data(data, len(data), None)
    if not handle:
        sys.exit("plot_png.py: librsvg could not read the plot")
    surface = cairo.cairo_image_surface_create(0, int(width * scale), int(height * scale))  # ARGB32
    cr = cairo.cairo_create(surface)
    cairo.cairo_set_source_rgb(cr, 1.0, 1.0, 1.0)
    cairo.cairo_paint(cr)
    cairo.cairo_scale(cr, scale, scale)
    if not rsvg.rsvg_handle_render_cairo(handle, cr):
        sys.exit("plot_png.py: librsvg could not draw the plot")
    status = cairo.cairo_surface_write_to_png(surface, out.encode())
    cairo.cairo_destroy(cr)
    cairo.cairo_surface_destroy(surface)
    if status != 0:
        sys.exit(f"plot_png.py: {out}: cairo could not write it (status {status})")


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    report, title, out = sys.argv[1:]
    with open(report, encoding="utf-8") as f:
        html = f.read()
    svg = find_svg(html, title)
    if svg is None:
        sys.exit(f"plot_png.py: {report}: no plot titled '{title}...'")
    render(svg, out)


if __name__ == "__main__":
    main()
