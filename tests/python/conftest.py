"""Paths for the module's tests, set by CTest (tests/python in the build): the built module's
directory, the CLI, the source tree and a scratch directory of the test's own."""
import os
import pathlib
import sys

import pytest

sys.path.insert(0, os.environ.get("SHELFDOCK_PYTHON_DIR", "build/python"))


@pytest.fixture(scope="session")
def source_dir():
    return pathlib.Path(os.environ.get("SHELFDOCK_SOURCE_DIR", ".")).resolve()


@pytest.fixture(scope="session")
def cli():
    return os.environ.get("SHELFDOCK_CLI", "build/bin/shelfdock")


@pytest.fixture(scope="session")
def models(source_dir):
    return source_dir / "config" / "models.yaml"
