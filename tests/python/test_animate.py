# pak.animate: the animated SVG `pak animate` writes, frames, errors, threads, progress.
import json
import subprocess

import numpy as np
import pytest

import pak

# Few slices, frames and iterations: a run of a second or so.
OPTIONS = dict(seed=3, max_iterations=60, threads=1)
FLAGS = ["--seed", "3", "--max-iterations", "60", "--threads", "1"]


def script(source):
    stars = source / "examples/animate/stars/elements"
    return {"slices": 8, "frames": 6, "loop": True, "duration": 2, "elements": [
        {"id": "a", "svg": str(stars / "star5.svg"), "count": 2,
         "rotation": [{"t": 0, "value": 0}, {"t": 1, "value": 72}]},
        {"id": "b", "svg": str(stars / "star4.svg"), "count": 2}]}


@pytest.fixture
def animation(source, tmp_path):
    path = tmp_path / "animation.json"
    path.write_text(json.dumps(script(source)))
    return path


def disc(source):
    return str(source / "examples/animate/stars/disc.svg")


def test_the_animated_svg_is_the_one_the_cli_writes(source, pak_binary, tmp_path, animation):
    out = tmp_path / "cli"
    subprocess.run([pak_binary, "animate", "-q", "-c", disc(source), "-a", str(animation), *FLAGS, "--svg-keyframes",
                    "4", "--no-gif", "-o", str(out), "--report", str(tmp_path / "cli.json")], check=True)
    result = pak.animate(disc(source), animation, svg_keyframes=4, **OPTIONS)
    assert result.to_svg() == (out / "animation.svg").read_text()
    result.save(tmp_path / "module.svg")
    assert (tmp_path / "module.svg").read_bytes() == (out / "animation.svg").read_bytes()
    report = json.loads((tmp_path / "cli.json").read_text())
    # The same report, but for the times.
    timeless = lambda r: {k: v for k, v in r.items() if "seconds" not in k}
    assert timeless(result.report) == timeless(report)


def test_the_frames_outlines_and_pngs(source, animation, tmp_path):
    result = pak.animate(disc(source), animation, evenness_frames=0, **OPTIONS)
    assert len(result) == 6 and np.allclose(result.times, np.arange(6) / 6)
    assert len(result.outlines) == 6
    for frame in result.outlines:
        assert len(frame) == len(result.colors) == len(result.sources) == 4
        assert all(ring.ndim == 2 and ring.shape[1] == 2 for outline in frame for ring in outline)
    # Frame i is the frame at its t, and any t can be drawn.
    first = result.outlines_at(0.0)
    assert all(np.array_equal(a, b) for x, y in zip(first, result.outlines[0]) for a, b in zip(x, y))
    assert result.to_png(200, t=0.3)[:8] == b"\x89PNG\r\n\x1a\n"
    assert result.frame_svg(0.5).startswith("<?xml") or "<svg" in result.frame_svg(0.5)
    result.save_gif(tmp_path / "a.gif", width=64)
    assert (tmp_path / "a.gif").read_bytes()[:6] == b"GIF89a"
    with pytest.raises(pak.InputError):
        result.to_png(t=1.5)


def test_a_dict_script_and_a_container_from_rings(source):
    t = np.linspace(0.0, 2.0 * np.pi, 64, endpoint=False)
    ring = np.column_stack([100 * np.cos(t), 100 * np.sin(t)])
    result = pak.animate(ring, script(source), frames=3, evenness_frames=0, **OPTIONS)
    assert len(result) == 3


def test_threads_do_not_change_the_result(source, animation):
    one = pak.animate(disc(source), animation, seed=5, max_iterations=60, threads=1, evenness_frames=0)
    two = pak.animate(disc(source), animation, seed=5, max_iterations=60, threads=2, evenness_frames=0)
    assert one.to_svg() == two.to_svg()


def test_bad_options_raise_the_cli_message(source, pak_binary, tmp_path, animation):
    def cli_error(*flags, script=animation):
        run = subprocess.run([pak_binary, "animate", "-q", "-c", disc(source), "-a", str(script), *flags,
                              "-o", str(tmp_path / "out")], capture_output=True, text=True)
        assert run.returncode == 2
        return run.stderr.strip()

    with pytest.raises(pak.InputError) as error:
        pak.animate(disc(source), animation, mirror="y=3")
    assert "pak: error: " + str(error.value) == cli_error("--mirror", "y=3")
    with pytest.raises(pak.InputError) as error:
        pak.animate(disc(source), animation, svg_keyframes=1)
    assert "pak: error: " + str(error.value) == cli_error("--svg-keyframes", "1")
    config = tmp_path / "config.json"
    config.write_text('{"slices": "many"}')
    with pytest.raises(pak.InputError) as error:
        pak.animate(disc(source), animation, slices="many")
    assert "pak: error: " + str(error.value) == cli_error("--config", str(config)).replace(str(config), "pak.animate")
    missing = tmp_path / "missing.json"
    with pytest.raises(pak.InputError) as error:
        pak.animate(disc(source), missing)
    assert "pak: error: " + str(error.value) == cli_error(script=missing)


def test_progress_is_called_and_its_exception_stops_the_run(source, animation):
    seen = []
    pak.animate(disc(source), animation, progress=seen.append, progress_every=10, evenness_frames=0, **OPTIONS)
    assert seen and {"iteration", "fill", "growing_slices"} <= set(seen[0])
    # The settle after the stop counts its steps down to the last call.
    assert seen[0]["settle_left"] == -1 and seen[-1]["settle_left"] == 0
    assert [p["settle_left"] for p in seen if p["settle_left"] >= 0] == list(range(90, -1, -10))

    def stop(progress):
        raise KeyError("stop")

    with pytest.raises(KeyError):
        pak.animate(disc(source), animation, progress=stop, progress_every=10, **OPTIONS)
