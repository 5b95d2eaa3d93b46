"""rayset.render against raytrace's OpenEXR of the same scene, size, passes and seed."""

from pathlib import Path

import numpy as np
import OpenEXR
import pytest

import rayset
from conftest import ROOT, run, tool

SCENES = ROOT / "tests" / "tracer" / "scenes"


def exr_channels(path) -> dict:
    with OpenEXR.File(str(path), separate_channels=True) as f:
        return {name: channel.pixels for name, channel in f.channels().items()}


@pytest.mark.parametrize("scene,passes,seed", [("cornell.pov", 3, 5), ("shapes.pov", 1, 0)])
def test_equals_raytrace_bit_for_bit(scene, passes, seed, tmp_path):
    out = tmp_path / "out.exr"
    run(tool("raytrace"), SCENES / scene, "+W40", "+H30", "-o", out, "--passes", passes,
        "--seed", seed, "-q")
    truth = exr_channels(out)
    image = rayset.render(SCENES / scene, width=40, height=30, passes=passes, seed=seed)
    assert image["rgb"].shape == (30, 40, 3) and image["rgb"].dtype == np.float32
    assert image["passes"] == passes
    for i, name in enumerate("RGB"):
        np.testing.assert_array_equal(image["rgb"][:, :, i], truth[name], err_msg=name)
    np.testing.assert_array_equal(image["Y"], truth["Y"])
    assert image["Y"].max() > 0


def test_scene_errors(tmp_path):
    scene = tmp_path / "bad.pov"
    scene.write_text("sphere { <0, 0, 0>, 1 pigment { rgb 1 }\n")
    with pytest.raises(rayset.Error, match="bad.pov"):
        rayset.render(scene, width=8, height=6, passes=1)
