# pak.flow: the same SVG as `pak flow`, its options' errors, threads, progress.
import json
import subprocess

import numpy as np
import pytest

import pak

# Few elements and refinement iterations: a run of a second or so.
OPTIONS = dict(seed=3, count=16, iterations=2, threads=1)
FLAGS = ["--seed", "3", "--count", "16", "--iterations", "2", "--threads", "1"]


def scene(source):
    return str(source / "examples/flow/koi.svg")


def elements(source):
    return str(source / "examples/flow/elements")


@pytest.mark.parametrize("more, more_flags", [
    ({}, []),
    (dict(spacing="1mm", polyline=True, infill_every=1), ["--spacing", "1mm", "--polyline", "--infill-every", "1"]),
])
def test_the_svg_is_the_one_the_cli_writes(source, pak_binary, tmp_path, more, more_flags):
    cli = tmp_path / "cli.svg"
    subprocess.run([pak_binary, "flow", "-q", scene(source), "--elements", elements(source), *FLAGS, *more_flags,
                    "-o", str(cli), "--report", str(tmp_path / "cli.json")], check=True)
    result = pak.flow(scene(source), elements(source), **OPTIONS, **more)
    assert result.to_svg() == cli.read_text()
    result.save(tmp_path / "module.svg")
    assert (tmp_path / "module.svg").read_bytes() == cli.read_bytes()
    report = json.loads((tmp_path / "cli.json").read_text())
    # The same report, but for the times.
    timeless = lambda r: {k: v for k, v in r.items() if "seconds" not in k}
    assert timeless(result.report) == timeless(report)


def test_the_result_holds_outlines_spines_colours_and_a_png(source):
    result = pak.flow(scene(source), elements(source), **OPTIONS)
    assert len(result) == len(result.outlines) == len(result.spines) == len(result.colors) == len(result.sources) > 0
    for outline, spine in zip(result.outlines, result.spines):
        assert all(ring.ndim == 2 and ring.shape[1] == 2 for ring in outline)
        assert spine.shape[1] == 2 and len(spine) >= 2
    assert all(c.startswith("#") for c in result.colors)
    assert all(s.endswith(".svg") for s in result.sources)
    assert result.to_png(200)[:8] == b"\x89PNG\r\n\x1a\n"


def test_a_container_from_rings_with_guides():
    t = np.linspace(0.0, 2.0 * np.pi, 64, endpoint=False)
    disc = np.column_stack([100 * np.cos(t), 100 * np.sin(t)])
    leaf = np.array([[0, 0], [10, -3], [20, 0], [10, 3]], dtype=float)
    result = pak.flow(disc, [leaf], guides=[[[-100, 0], [100, 0]]], seed=1, count=12, iterations=1, threads=1)
    assert len(result) > 0
    with pytest.raises(pak.InputError, match="guide"):
        pak.flow(disc, [leaf], seed=1, count=12, iterations=1)


def test_threads_do_not_change_the_result(source):
    one = pak.flow(scene(source), elements(source), seed=5, count=16, iterations=2, threads=1)
    two = pak.flow(scene(source), elements(source), seed=5, count=16, iterations=2, threads=2)
    assert one.to_svg() == two.to_svg()


def test_bad_options_raise_the_cli_message(source, pak_binary, tmp_path):
    # The CLI names the --config file where the module names pak.flow; the rest is the same.
    config = tmp_path / "config.json"
    for options in [dict(iterations="many"), dict(no_such_option=1)]:
        config.write_text(json.dumps({k.replace("_", "-"): v for k, v in options.items()}))
        cli = subprocess.run([pak_binary, "flow", "-q", scene(source), "--elements", elements(source), "--config",
                              str(config), "-o", str(tmp_path / "out.svg")], capture_output=True, text=True)
        assert cli.returncode == 2
        with pytest.raises(pak.InputError) as error:
            pak.flow(scene(source), elements(source), **options)
        assert "pak: error: " + str(error.value) == cli.stderr.strip().replace(str(config), "pak.flow")
    cli = subprocess.run([pak_binary, "flow", "-q", scene(source), "--elements", elements(source), "--mirror", "z=3",
                          "-o", str(tmp_path / "out.svg")], capture_output=True, text=True)
    with pytest.raises(pak.InputError) as error:
        pak.flow(scene(source), elements(source), mirror="z=3")
    assert "pak: error: " + str(error.value) == cli.stderr.strip()


def test_progress_is_called_and_its_exception_stops_the_run(source):
    seen = []
    pak.flow(scene(source), elements(source), progress=seen.append, **OPTIONS)
    assert [p["phase"] for p in seen if p["phase"] == "refinement"] == ["refinement"] * 2
    assert {"phase", "iteration", "iterations", "elements", "element_area"} <= set(seen[-1])

    def stop(progress):
        raise KeyError("stop")

    with pytest.raises(KeyError):
        pak.flow(scene(source), elements(source), progress=stop, **OPTIONS)
