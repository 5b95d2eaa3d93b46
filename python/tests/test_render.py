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


def test_image_maps_are_read_as_raytrace_reads_them(tmp_path):
    # Images come through a module the package carries beside the extension; a gradient that
    # raytrace wrote as PNG, mapped on a plane, renders as raytrace renders it.
    camera = "camera { orthographic location <0.5, 0.5, -1> look_at <0.5, 0.5, 0> right x up y }"
    finish = "finish { emission 1 ambient 0 diffuse 0 }"
    (tmp_path / "gradient.pov").write_text(
        f"#version 3.7;\n{camera}\nplane {{ z, 0 pigment {{ gradient x }} {finish} }}\n")
    run(tool("raytrace"), "gradient.pov", "+W16", "+H4", "--passes", 1, "-o", "gradient.png",
        "-q", cwd=tmp_path)
    scene = tmp_path / "mapped.pov"
    image_map = 'pigment { image_map { png "gradient.png" } }'
    scene.write_text(f"#version 3.7;\n{camera}\nplane {{ z, 0 {image_map} {finish} }}\n")
    run(tool("raytrace"), scene, "+W16", "+H4", "--passes", 1, "-o", tmp_path / "mapped.exr",
        "-q")
    truth = exr_channels(tmp_path / "mapped.exr")
    image = rayset.render(scene, width=16, height=4, passes=1)
    np.testing.assert_array_equal(image["Y"], truth["Y"])
    row = image["Y"][0]
    assert np.all(np.diff(row) > 0), row  # the gradient itself, left to right
