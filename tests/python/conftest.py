"""Paths for the module's tests, set by CTest (tests/python in the build): the built module's
directory, the CLI, the source tree and a scratch directory of the test's own; and the source
tree's scripts, loaded by path."""
import importlib.util
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


@pytest.fixture(scope="session")
def load_script(source_dir):
    """load_script(name): scripts/<name>.py as a module, loaded by path (the scripts are no
    package); the scripts directory goes on sys.path for the imports between them."""
    scripts = source_dir / "scripts"

    def load(name):
        if str(scripts) not in sys.path:
            sys.path.insert(0, str(scripts))
        spec = importlib.util.spec_from_file_location(name, scripts / f"{name}.py")
        module = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(module)
        return module

    return load
