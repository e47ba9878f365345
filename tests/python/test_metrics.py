# pak.metrics: the figures of `pak metrics --json`, from a file or a result, its option table.
import json
import subprocess

import numpy as np
import pytest

import pak

# A coarse grid and few radii: quick, as the CLI tests measure.
OPTIONS = dict(radii=20, grid=200, bins=10)
FLAGS = ["--radii", "20", "--grid", "200", "--bins", "10"]


def same(module, cli, where="metrics"):
    """The module's dict equals the CLI's JSON, its lists of numbers numpy arrays."""
    if isinstance(module, np.ndarray):
        assert np.array_equal(module, np.asarray(cli, dtype=float)), where
    elif isinstance(module, dict):
        assert set(module) == set(cli), where
        for key in module:
            same(module[key], cli[key], where + "." + key)
    else:
        assert module == cli, where


@pytest.fixture(scope="module")
def packed(source, pak_binary, tmp_path_factory):
    folder = tmp_path_factory.mktemp("metrics")
    subprocess.run([pak_binary, "pack", "-q", "-c", str(source / "examples/scene.svg"), "-e",
                    str(source / "examples/elements/fish.svg"), str(source / "examples/elements/leaf.svg"),
                    "--seed", "3", "--max-iterations", "60", "--threads", "1", "-o", str(folder / "packing.svg"),
                    "--report", str(folder / "report.json")], check=True)
    return folder


def cli_metrics(pak_binary, files, *flags):
    out = files[0].parent / "metrics.json"
    subprocess.run([pak_binary, "metrics", *map(str, files), *FLAGS, *flags, "--json", str(out)], check=True,
                   capture_output=True)
    return json.loads(out.read_text())["packings"]


def test_a_file_gives_the_cli_figures(pak_binary, packed):
    cli = cli_metrics(pak_binary, [packed / "packing.svg"], "--report", str(packed / "report.json"))[0]
    module = pak.metrics(packed / "packing.svg", report=packed / "report.json", **OPTIONS)
    same(module, cli)
    assert isinstance(module["curves"]["Q"]["r"], np.ndarray) and isinstance(module["evenness"]["P2"], float)
    assert not module["d_gap-estimated"]


def test_a_pack_result_is_measured_with_its_own_report(source, pak_binary, packed):
    result = pak.pack(str(source / "examples/scene.svg"),
                      [str(source / "examples/elements/fish.svg"), str(source / "examples/elements/leaf.svg")],
                      seed=3, max_iterations=60, threads=1)
    cli = cli_metrics(pak_binary, [packed / "packing.svg"], "--report", str(packed / "report.json"))[0]
    module = pak.metrics(result, **OPTIONS)
    module["file"] = cli["file"]  # the result has no file
    same(module, cli)


def test_several_packings_with_calibrate_and_a_gap(pak_binary, packed, tmp_path):
    second = tmp_path / "second.svg"
    second.write_bytes((packed / "packing.svg").read_bytes())
    cli = cli_metrics(pak_binary, [packed / "packing.svg", second], "--calibrate", "--gap", "6")
    module = pak.metrics([packed / "packing.svg", second], calibrate=True, gap=6.0, **OPTIONS)
    assert len(module) == 2
    for m, c in zip(module, cli):
        same(m, c)


def test_bad_options_raise_the_cli_message(pak_binary, packed, tmp_path):
    config = tmp_path / "config.json"
    for options in [dict(grid="fine"), dict(no_such_option=1)]:
        config.write_text(json.dumps({k.replace("_", "-"): v for k, v in options.items()}))
        cli = subprocess.run([pak_binary, "metrics", str(packed / "packing.svg"), "--config", str(config)],
                             capture_output=True, text=True)
        assert cli.returncode == 2
        with pytest.raises(pak.InputError) as error:
            pak.metrics(packed / "packing.svg", **options)
        assert "pak: error: " + str(error.value) == cli.stderr.strip().replace(str(config), "pak.metrics")
    missing = str(tmp_path / "missing.svg")
    cli = subprocess.run([pak_binary, "metrics", missing], capture_output=True, text=True)
    with pytest.raises(pak.InputError) as error:
        pak.metrics(missing)
    assert "pak: error: " + str(error.value) == cli.stderr.strip()
