# pak.pack: the same SVG as `pak pack`, numpy inputs, errors, threads.
import subprocess

import numpy as np
import pytest

import pak

# Few iterations and two elements: a quick run that still packs something.
OPTIONS = dict(seed=3, max_iterations=60, threads=1)
FLAGS = ["--seed", "3", "--max-iterations", "60", "--threads", "1"]


def elements(source):
    return [str(source / "examples/elements/fish.svg"), str(source / "examples/elements/leaf.svg")]


def circle(radius, n=48, centre=(0.0, 0.0)):
    t = np.linspace(0.0, 2.0 * np.pi, n, endpoint=False)
    return np.column_stack([centre[0] + radius * np.cos(t), centre[1] + radius * np.sin(t)])


# Plain options; then a preset, a length with a unit, a text option and a flag.
@pytest.mark.parametrize("more, more_flags", [
    ({}, []),
    (dict(preset="rigid", gap="1.5mm", orientation="upright", polyline=True),
     ["--preset", "rigid", "--gap", "1.5mm", "--orientation", "upright", "--polyline"]),
])
def test_the_svg_is_the_one_the_cli_writes(source, pak_binary, tmp_path, more, more_flags):
    cli = tmp_path / "cli.svg"
    subprocess.run([pak_binary, "pack", "-q", "--container", str(source / "examples/scene.svg"),
                    "--elements", *elements(source), *FLAGS, *more_flags, "-o", str(cli)], check=True)
    result = pak.pack(str(source / "examples/scene.svg"), elements(source), **OPTIONS, **more)
    assert result.to_svg() == cli.read_text()
    result.save(tmp_path / "module.svg")
    assert (tmp_path / "module.svg").read_bytes() == cli.read_bytes()


def test_read_scene_and_elements_give_the_same_packing_as_paths(source):
    by_path = pak.pack(str(source / "examples/scene.svg"), elements(source), **OPTIONS)
    read = pak.pack(pak.read_scene(source / "examples/scene.svg"), pak.read_elements(elements(source)), **OPTIONS)
    assert read.to_svg() == by_path.to_svg()


def test_numpy_container_and_elements():
    square = np.array([[0, 0], [10, 0], [10, 10], [0, 10]], dtype=float)
    triangle = [[0, 0], [12, 0], [6, 9]]
    result = pak.pack(circle(100.0), [square, triangle], seed=1, max_iterations=60, threads=1)
    assert len(result) > 0
    assert result.sources and set(result.colors) == {"#3b6ea5"}
    for outline in result.outlines:
        for ring in outline:
            assert ring.ndim == 2 and ring.shape[1] == 2
            assert np.all(np.hypot(ring[:, 0], ring[:, 1]) < 101.0)  # inside the container
    assert result.report["parameters"]["seed"] == 1
    assert result.to_png(200)[:8] == b"\x89PNG\r\n\x1a\n"


def test_a_container_with_a_hole_from_rings():
    scene = pak.scene([circle(100.0), circle(30.0)])
    assert len(scene.container) == 2  # the outer ring and the hole


def test_threads_do_not_change_the_result(source):
    one = pak.pack(str(source / "examples/scene.svg"), elements(source), seed=5, max_iterations=60, threads=1)
    two = pak.pack(str(source / "examples/scene.svg"), elements(source), seed=5, max_iterations=60, threads=2)
    assert one.to_svg() == two.to_svg()


def test_a_missing_file_raises_the_cli_message(source, pak_binary, tmp_path):
    missing = str(tmp_path / "missing.svg")
    cli = subprocess.run([pak_binary, "pack", "-q", "--container", missing, "--elements", *elements(source),
                          "-o", str(tmp_path / "out.svg")], capture_output=True, text=True)
    assert cli.returncode == 2
    with pytest.raises(pak.InputError) as error:
        pak.pack(missing, elements(source))
    assert "pak: error: " + str(error.value) == cli.stderr.strip()


def test_bad_options_raise_input_error(source):
    with pytest.raises(pak.InputError, match='unknown option "no-such-option"'):
        pak.pack(circle(100.0), elements(source), no_such_option=1)
    with pytest.raises(pak.InputError, match='"seed" must be a non-negative integer'):
        pak.pack(circle(100.0), elements(source), seed=-1)
    with pytest.raises(pak.InputError):
        pak.pack([[0, 0], [1, 1]], elements(source))  # two points make no ring


def test_progress_is_called_and_its_exception_stops_the_run(source):
    seen = []
    pak.pack(circle(100.0), elements(source), progress=seen.append, progress_every=10, **OPTIONS)
    assert seen and seen[0]["iteration"] >= 0

    def stop(progress):
        raise KeyError("stop")

    with pytest.raises(KeyError):
        pak.pack(circle(100.0), elements(source), progress=stop, **OPTIONS)


def test_ctrl_c_stops_a_run_with_keyboard_interrupt(source):
    import os
    import signal
    import threading
    import time

    timer = threading.Timer(0.5, lambda: os.kill(os.getpid(), signal.SIGINT))
    start = time.monotonic()
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            # A run that would go on for the whole time limit.
            pak.pack(circle(100.0), elements(source), seed=1, max_iterations=10**7, time_limit=20.0,
                     stall_epsilon=0.0, target_fill=0.999, progress_every=5)
    finally:
        timer.cancel()
    assert time.monotonic() - start < 15.0


def test_the_readers_warnings_are_input_warnings_as_the_cli_prints_them(pak_binary, tmp_path):
    # A colour that cannot be parsed is skipped with a warning, which the CLI prints on stderr.
    drawing = tmp_path / "red.svg"
    drawing.write_text('<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 10 10">'
                       '<rect width="10" height="10" style="fill:r\u00e9d"/></svg>', encoding="utf-8")
    cli = subprocess.run([pak_binary, "inspect", str(drawing)], capture_output=True, text=True, check=True)
    with pytest.warns(pak.InputWarning) as caught:
        pak.read_elements([str(drawing)])
    said = [str(w.message) for w in caught if issubclass(w.category, pak.InputWarning)]
    assert said == [f'{drawing}: <rect>: ignored fill="r\u00e9d" (cannot be parsed)']
    assert said[0] in cli.stdout
    assert issubclass(pak.InputWarning, UserWarning)
