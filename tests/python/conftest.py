# The module under test comes from PYTHONPATH (CMake's Python.ModuleTests sets it to the
# release build's python/ folder), the CLI to compare with from PAK_BINARY.
import os
import pathlib

import pytest

SOURCE = pathlib.Path(os.environ.get("PAK_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))


@pytest.fixture(scope="session")
def source():
    return SOURCE


@pytest.fixture(scope="session")
def pak_binary():
    binary = os.environ.get("PAK_BINARY")
    if not binary or not os.access(binary, os.X_OK):
        pytest.skip("PAK_BINARY does not name the pak tool")
    return binary
