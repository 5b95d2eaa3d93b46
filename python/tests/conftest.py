"""Fixtures: the C++ tools of the same build (the independent truths the module is compared
with) and ray files they synthesise with fixed seeds."""

import json
import os
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
# The build whose tools the tests run: RAYSET_BUILD_DIR, else the build folder of this checkout.
BUILD = Path(os.environ.get("RAYSET_BUILD_DIR", ROOT / "build"))


def tool(name: str) -> Path:
    for folder in ("converters", "lightmodel", "tracer", "viz"):
        path = BUILD / folder / name
        if path.is_file():
            return path
    pytest.fail(f"{name} is not built in {BUILD} (set RAYSET_BUILD_DIR)")


def run(*args, cwd=None) -> str:
    result = subprocess.run([str(a) for a in args], capture_output=True, text=True, cwd=cwd)
    if result.returncode != 0:
        pytest.fail(f"{' '.join(map(str, args))} failed:\n{result.stdout}{result.stderr}")
    return result.stdout


def rayconv(*args, **kw) -> str:
    return run(tool("rayconv"), *args, **kw)


def info(path) -> dict:
    return json.loads(rayconv("info", path, "--json"))


@pytest.fixture(scope="session")
def data(tmp_path_factory) -> Path:
    return tmp_path_factory.mktemp("data")


@pytest.fixture(scope="session")
def disk(data) -> Path:
    """A Lambertian disk of radius 1 mm and 1 W at 555 nm: 20000 rays, seed 7."""
    path = data / "disk.tm25ray"
    rayconv("synth", "disk", "--rays", 20000, "--seed", 7, "-o", path)
    return path


@pytest.fixture(scope="session")
def cluster(data) -> Path:
    """Seven chips of three colours, a wavelength per ray (TM-25 then holds radiant flux
    only): 30000 rays."""
    path = data / "cluster.tm25ray"
    rayconv("synth", "cluster", "rings=1,6", "--rays", 30000, "--seed", 11, "-o", path)
    return path
