#!/usr/bin/python3
"""A generated blob filled with generated shapes: a seed sweep keeps the most even packing.

Run from the repository root after `make python`:
    PYTHONPATH=build/release/python /usr/bin/python3 examples/python/blob_sweep.py [OUT_DIR]
Writes OUT_DIR/blob.svg (for a plotter or Inkscape), OUT_DIR/blob.png and prints each seed's P2.
Three runs of up to 1500 iterations: about 15 seconds on two cores.
"""
import pathlib
import sys

import numpy as np

import pak


def blob(radius=300.0, points=180, seed=7):
    """A closed outline whose radius wanders smoothly: a few random low harmonics."""
    rng = np.random.default_rng(seed)
    t = np.linspace(0.0, 2.0 * np.pi, points, endpoint=False)
    r = np.ones_like(t)
    for k in range(2, 6):
        r += rng.uniform(0.03, 0.12) / k * np.sin(k * t + rng.uniform(0.0, 2.0 * np.pi))
    return np.column_stack([radius * r * np.cos(t), radius * r * np.sin(t)])


def star(arms=5, inner=0.45, size=20.0):
    t = np.linspace(0.0, 2.0 * np.pi, 2 * arms, endpoint=False)
    r = np.where(np.arange(2 * arms) % 2 == 0, 1.0, inner) * size
    return np.column_stack([r * np.sin(t), -r * np.cos(t)])


def ellipse(a=22.0, b=11.0, points=32):
    t = np.linspace(0.0, 2.0 * np.pi, points, endpoint=False)
    return np.column_stack([a * np.cos(t), b * np.sin(t)])


def ring(outer=16.0, inner=7.0, points=32):
    """A washer: an outer ring and a hole (even-odd)."""
    return [ellipse(outer, outer, points), ellipse(inner, inner, points)[::-1]]


def main():
    out = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "out/python")
    out.mkdir(parents=True, exist_ok=True)
    container = pak.scene(blob())
    shapes = pak.elements([star(), ellipse(), ring()], colors=["#e07a5f", "#3d405b", "#81b29a"])

    # The same options for every seed; only the seed changes. P2 (the share of the negative
    # space in pockets) is lower for a more even packing.
    best = None
    for seed in range(1, 4):
        result = pak.pack(container, shapes, seed=seed, max_iterations=1500, threads=2)
        p2 = result.report["evenness"]["P2"]
        print(f"seed {seed}: {len(result)} elements, art fill {result.report['fill-ratio-art']:.3f}, P2 {p2:.3f}")
        if best is None or p2 < best[1]:
            best = (seed, p2, result)

    seed, p2, result = best
    result.save(out / "blob.svg")
    (out / "blob.png").write_bytes(result.to_png(800))
    print(f"kept seed {seed} (P2 {p2:.3f}): {out / 'blob.svg'}, {out / 'blob.png'}")


if __name__ == "__main__":
    main()
