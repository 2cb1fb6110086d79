#!/usr/bin/env python3
# Copyright (c) 2026 Lattice_mesher_3 developers.
# SPDX-License-Identifier: GPL-3.0-or-later
#
# lattice-mesh --png read back by an independent reader (Pillow): the picture has its size; the
# left view (the boundary, grey) and the right view (the clipped tetrahedra, coloured by theta_min)
# are both drawn, under one camera (what the right view covers, the left covers too); the colour
# bar runs from viridis' yellow at the top to its dark purple, with the red swatch below; red
# appears in the right view only if the mesh has tetrahedra below 40 degrees (--stats). An output
# that cannot be written is an error before any work.
#
#   png.py --lattice-mesh BIN --out DIR [lattice-mesh arguments...]

import argparse
import json
import os
import subprocess
import sys

import numpy as np
from PIL import Image

WIDTH, HEIGHT = 1600, 800      # render_png::Picture_options
VIEW_WIDTH, CAPTION = 0.44, 0.14   # render_png.cpp: the layout
VIRIDIS = np.array([[0.267004, 0.004874, 0.329415], [0.282623, 0.140926, 0.457517], [0.229739, 0.322361, 0.545706],
                    [0.172719, 0.448791, 0.557885], [0.127568, 0.566949, 0.550556], [0.134692, 0.658636, 0.517649],
                    [0.369214, 0.788888, 0.382914], [0.678489, 0.863742, 0.189503], [0.993248, 0.906157, 0.143936]]) * 255


def viridis(t):
    """viridis at t in [0, 1], as render_png.cpp interpolates it"""
    x = t * 8
    i = min(int(x), 7)
    return VIRIDIS[i] + (x - i) * (VIRIDIS[i + 1] - VIRIDIS[i])


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument('--lattice-mesh', required=True)
    parser.add_argument('--out', required=True)
    args, rest = parser.parse_known_args()
    os.makedirs(args.out, exist_ok=True)
    failures = []

    def check(ok, what):
        print(('ok    ' if ok else 'FAIL  ') + what)
        if not ok:
            failures.append(what)

    # an unwritable picture: an error before any work (nothing printed on stdout)
    bad = subprocess.run([args.lattice_mesh] + rest + ['--png', os.path.join(args.out, 'no-such-dir', 'x.png')],
                         capture_output=True, text=True)
    check(bad.returncode != 0 and 'cannot write' in bad.stderr and bad.stdout == '',
          '--png into a missing folder fails before any work: ' + bad.stderr.strip())

    picture, stats = os.path.join(args.out, 'picture.png'), os.path.join(args.out, 'picture.json')
    for f in (picture, stats):
        if os.path.exists(f):
            os.remove(f)
    subprocess.run([args.lattice_mesh] + rest + ['--png', picture, '--stats', stats, '--quiet'],
                   check=True, stdout=subprocess.DEVNULL)
    below40 = json.load(open(stats))['below40']
    image = Image.open(picture)
    check(image.format == 'PNG' and image.size == (WIDTH, HEIGHT), f'a {WIDTH}x{HEIGHT} PNG: {image.format} {image.size}')
    rgb = np.asarray(image.convert('RGB')).astype(int)
    if rgb.shape != (HEIGHT, WIDTH, 3):
        sys.exit('FAILED: ' + '; '.join(failures))

    w, top = int(VIEW_WIDTH * WIDTH), int(CAPTION * HEIGHT) + 2   # the views below their captions
    left, right, legend = rgb[top:, :w], rgb[top:, w:2 * w], rgb[:, 2 * w:]
    drawn = lambda a: (a < 235).any(axis=2)   # noqa: E731   the background is white
    saturation = lambda a: a.max(axis=2) - a.min(axis=2)   # noqa: E731
    red = lambda a: (a[..., 0] > 150) & (a[..., 1] < 60) & (a[..., 2] < 60)   # noqa: E731
    left_drawn, right_drawn = drawn(left), drawn(right)
    check(left_drawn.mean() > 0.10, f'the left view is drawn: {left_drawn.mean():.1%} of it')
    check(right_drawn.mean() > 0.05, f'the right view is drawn: {right_drawn.mean():.1%} of it')
    grey = (saturation(left)[left_drawn] < 40).mean() if left_drawn.any() else 0
    check(grey > 0.98, f'the boundary is grey: {grey:.1%} of its pixels')
    coloured = (saturation(right)[right_drawn] > 40).mean() if right_drawn.any() else 0
    check(coloured > 0.30, f'the clipped tetrahedra are coloured: {coloured:.1%} of their pixels')
    # one camera: the clipped part of the mesh is inside the whole mesh
    inside = left_drawn[right_drawn].mean() if right_drawn.any() else 0
    check(inside > 0.97, f'the right view lies within the left one: {inside:.1%} of its pixels')
    red_pixels = int(red(right).sum())
    check(below40 > 0 or red_pixels == 0, f'red in the right view only with tetrahedra below 40 degrees: '
          f'{red_pixels} red pixels, {below40} below 40')

    # the colour bar: the legend's column with the most saturated pixels, top to bottom viridis
    # from yellow to dark purple (0 to 1 in steps), then the red swatch
    bar_column = int(np.argmax((saturation(legend) > 40).sum(axis=0)))
    column = legend[:, bar_column]
    in_bar = np.flatnonzero((saturation(column[None])[0] > 40) & ~red(column[None])[0])
    reds = np.flatnonzero(red(column[None])[0])
    check(len(in_bar) > 0.5 * HEIGHT, f'the colour bar is at least half the height: {len(in_bar)} pixels')
    if len(in_bar) > 10:
        first, last = in_bar[0], in_bar[-1]
        worst = 0
        for k in range(11):
            y = first + (last - first) * k // 10
            worst = max(worst, np.abs(column[y] - viridis(1 - k / 10)).max())
        check(worst < 25, f'the colour bar is viridis from yellow (70.5) to dark purple (40): off by {worst:.0f} at most')
        check(len(reds) > 5 and reds.min() > last, f'the red swatch is below the bar: {len(reds)} red pixels')
    if failures:
        sys.exit('FAILED: ' + '; '.join(failures))
    print('the picture shows the mesh')


if __name__ == '__main__':
    main()
