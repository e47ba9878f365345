#!/usr/bin/python3
"""pak.flow and pak.animate from plain data: a shapely container with guides drawn as lines,
and an animation given as a dict.

Run from the repository root after `make python`:
    PYTHONPATH=build/release/python /usr/bin/python3 examples/python/flow_and_animate.py [OUT_DIR]
Writes OUT_DIR/flow.svg and flow.png (leaves bent along two guides around a hole),
OUT_DIR/stars.svg (an animated SVG: open it in a browser), stars.gif and stars-t0.5.png, and
prints how even the flow is (pak.metrics). Half a minute or so on two cores.
"""
import pathlib
import sys

import numpy as np
from shapely.geometry import LineString, Point, Polygon

import pak

ROOT = pathlib.Path(__file__).resolve().parents[2]


def main():
    out = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "out/python")
    out.mkdir(parents=True, exist_ok=True)

    # FLOWPAK: the streamlines follow the guides; each leaf is bent along one.
    ring = Point(0, 0).buffer(200).difference(Point(60, 0).buffer(60))
    t = np.linspace(-200, 200, 50)
    guides = [LineString(np.column_stack([t, -120 + 40 * np.sin(t / 60)])),
              LineString(np.column_stack([t, 120 - 40 * np.sin(t / 60)]))]
    leaf = Polygon([(0, 0), (12, -4), (30, 0), (12, 4)])
    blade = Polygon([(0, 0), (25, -2.5), (60, 0), (25, 2.5)])  # for the longer streamlines
    flow = pak.flow(ring, pak.elements([leaf, blade], colors=["#4f772d", "#90a955"]), guides=guides,
                    seed=4, count=60, iterations=4, threads=2)
    flow.save(out / "flow.svg")
    (out / "flow.png").write_bytes(flow.to_png(600))
    figures = pak.metrics(flow)
    print(f"flow: {len(flow)} leaves, negative space {figures['negative-ratio']:.3f}, "
          f"P2 {figures['evenness']['P2']:.4f}")

    # AnimationPak: an animation file's JSON as a dict, its element paths absolute.
    stars = ROOT / "examples/animate/stars"
    script = {"slices": 20, "frames": 40, "loop": True, "duration": 4, "elements": [
        {"id": "spin", "svg": str(stars / "elements/star5.svg"), "count": 6,
         "rotation": [{"t": 0, "value": 0}, {"t": 1, "value": 72}]},
        {"id": "pulse", "svg": str(stars / "elements/star4.svg"), "count": 6,
         "scale": [{"t": 0, "value": 0.8}, {"t": 0.5, "value": 1.2}, {"t": 1, "value": 0.8}]}]}
    anim = pak.animate(str(stars / "disc.svg"), script, seed=2, max_iterations=1500, threads=2,
                       progress=lambda p: print(f"  iteration {p['iteration']}, fill {p['fill']:.3f}"),
                       progress_every=300)
    anim.save(out / "stars.svg")
    anim.save_gif(out / "stars.gif", width=300)
    (out / "stars-t0.5.png").write_bytes(anim.to_png(500, t=0.5))
    print(f"animate: {len(anim)} frames of {len(anim.outlines[0])} elements, "
          f"stop reason {anim.report['stop-reason']}")


if __name__ == "__main__":
    main()
