#!/usr/bin/python3
"""A blob from noise filled with shapely shapes; a seed sweep keeps the most even packing by
P2 (pak.metrics), written as a pen-plotter SVG: outlines only, one layer per pen colour.

Run from the repository root after `make python` (shapely: Debian's python3-shapely, which
scripts/install-deps.sh installs):
    PYTHONPATH=build/release/python /usr/bin/python3 examples/python/plotter_sweep.py [OUT_DIR]
Writes OUT_DIR/plotter.svg (for vpype, Inkscape or an AxiDraw: a layer per pen),
OUT_DIR/packing.svg and OUT_DIR/packing.png (the packing as `pak pack` writes it) and
OUT_DIR/seed-N.png (each seed's, to compare); prints each seed's figures. Ten seconds or so
on two cores.
"""
import pathlib
import sys

import numpy as np
from shapely import affinity
from shapely.geometry import Point, Polygon
from shapely.ops import unary_union

import pak


def noise(t, seed, octaves=4):
    """Smooth periodic noise in [-1, 1] along the angle t: random harmonics, weaker as they rise."""
    rng = np.random.default_rng(seed)
    value = np.zeros_like(t)
    for k in range(2, 2 + octaves):
        value += rng.uniform(0.5, 1.0) / k * np.sin(k * t + rng.uniform(0.0, 2.0 * np.pi))
    return value / np.abs(value).max()


def blob(radius, wobble, seed, centre=(0.0, 0.0), points=240):
    """A closed shape whose radius follows the noise."""
    t = np.linspace(0.0, 2.0 * np.pi, points, endpoint=False)
    r = radius * (1.0 + wobble * noise(t, seed))
    return Polygon(np.column_stack([centre[0] + r * np.cos(t), centre[1] + r * np.sin(t)]))


def container(seed=11):
    """A blob with a smaller blob cut out of it: shapely keeps the hole."""
    return blob(300.0, 0.25, seed).difference(blob(70.0, 0.3, seed + 1, centre=(60.0, -40.0)))


def shapes():
    """Shapely shapes: a star, a lens (two discs intersected), a washer (a disc with a hole) and
    a bean (discs united)."""
    t = np.linspace(0.0, 2.0 * np.pi, 10, endpoint=False)
    r = np.where(np.arange(10) % 2 == 0, 20.0, 9.0)
    star = Polygon(np.column_stack([r * np.sin(t), -r * np.cos(t)]))
    lens = Point(-9, 0).buffer(16).intersection(Point(9, 0).buffer(16))
    washer = Point(0, 0).buffer(15).difference(Point(0, 0).buffer(6))
    bean = unary_union([Point(x, 2.5 * np.sin(x / 5)).buffer(7) for x in np.linspace(-14, 14, 8)])
    return [star, affinity.scale(lens, 1.2, 0.8), washer, bean]


COLOURS = ["#e07a5f", "#3d405b", "#81b29a", "#f2cc8f"]  # one pen each


def path_data(rings):
    return " ".join("M" + " L".join(f"{x:.2f},{y:.2f}" for x, y in ring) + " Z" for ring in rings)


def plotter_svg(result, boundary, width_mm=200.0, margin=10.0):
    """The outlines as strokes, no fills: one Inkscape layer per colour, the container on its own."""
    x0, y0, x1, y1 = boundary.bounds
    x0, y0, x1, y1 = x0 - margin, y0 - margin, x1 + margin, y1 + margin
    height_mm = width_mm * (y1 - y0) / (x1 - x0)
    layers = {}
    for outline, colour in zip(result.outlines, result.colors):
        layers.setdefault(colour, []).append(path_data(outline))
    walls = [np.asarray(boundary.exterior.coords)[:-1]] + [np.asarray(r.coords)[:-1] for r in boundary.interiors]
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" xmlns:inkscape="http://www.inkscape.org/namespaces/inkscape" '
           f'width="{width_mm:.1f}mm" height="{height_mm:.1f}mm" viewBox="{x0:.2f} {y0:.2f} {x1 - x0:.2f} {y1 - y0:.2f}">',
           '<g inkscape:groupmode="layer" inkscape:label="0 container" fill="none" stroke="#000000" stroke-width="1">',
           f'<path d="{path_data(walls)}"/>', '</g>']
    for pen, (colour, paths) in enumerate(sorted(layers.items()), start=1):
        out.append(f'<g inkscape:groupmode="layer" inkscape:label="{pen} {colour}" fill="none" stroke="{colour}" '
                   f'stroke-width="1">')
        out += [f'<path d="{d}"/>' for d in paths]
        out.append("</g>")
    return "\n".join(out + ["</svg>", ""])


def main():
    out = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "out/python")
    out.mkdir(parents=True, exist_ok=True)
    boundary = container()
    elements = pak.elements(shapes(), colors=COLOURS)

    # The same options for every seed; only the seed changes. P2, the share of the negative
    # space in pockets wider than twice its typical half-width, is lower for a more even packing.
    results = []
    for seed in range(1, 5):
        result = pak.pack(boundary, elements, seed=seed, max_iterations=800, threads=2)
        figures = pak.metrics(result)
        p2 = figures["evenness"]["P2"]
        print(f"seed {seed}: {len(result)} elements, negative space {figures['negative-ratio']:.3f}, "
              f"h {figures['evenness']['h']:.2f}, P2 {p2:.4f}")
        results.append((p2, seed, result))

    p2, seed, best = min(results, key=lambda r: r[0])
    (out / "plotter.svg").write_text(plotter_svg(best, boundary))
    best.save(out / "packing.svg")
    (out / "packing.png").write_bytes(best.to_png(800))
    for _, s, result in results:  # to compare the seeds by eye
        (out / f"seed-{s}.png").write_bytes(result.to_png(400))
    print(f"kept seed {seed} (P2 {p2:.4f}): {out / 'plotter.svg'}, {out / 'packing.svg'}, {out / 'packing.png'}")


if __name__ == "__main__":
    main()
