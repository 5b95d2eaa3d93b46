"""Photometry and far fields, against rayconv's files and figures and the disk's cosine law."""

import json

import numpy as np
import pytest

import rayset
from conftest import rayconv


@pytest.mark.parametrize("smoothing", ["none", "auto", "4"])
def test_far_field_file_equals_rayconv_farfield(smoothing, disk, tmp_path):
    theirs = tmp_path / f"cli_{smoothing}.ies"
    rayconv("farfield", disk, "-o", theirs, "--smoothing", smoothing, "--c-step", 10,
            "--gamma-step", 5)
    far = rayset.far_field(disk, c_step=10, gamma_step=5, smoothing=smoothing, round=True)
    ours = tmp_path / f"py_{smoothing}.ies"
    rayset.write_photometry(ours, far.photometry)
    assert ours.read_bytes() == theirs.read_bytes()


def test_far_field_of_lambertian_disk(disk):
    far = rayset.far_field(disk, c_step=10, gamma_step=5, smoothing="none", radiometric=True)
    p = far.photometry
    assert p.type == "C"
    np.testing.assert_array_equal(p.vertical_deg, np.arange(0, 180.1, 5))
    np.testing.assert_array_equal(p.horizontal_deg, np.arange(0, 360.1, 10))
    assert p.candela.shape == far.flux.shape == far.solid_angle.shape == (37, 37)
    assert far.rays == 20000
    # The cells' flux is the rays' flux (1 W) and tiles the sphere.
    assert far.total_flux == pytest.approx(1.0, rel=1e-6)
    assert far.flux[:-1].sum() == pytest.approx(1.0, rel=1e-6)  # row 360 repeats row 0
    assert far.solid_angle[:-1].sum() == pytest.approx(4 * np.pi, rel=1e-12)
    # A Lambertian disk of 1 W: I(gamma) = cos(gamma) / pi W/sr over the upper half. Averaged
    # over the C planes, each gamma row is within 4 standard errors of it.
    gamma = np.radians(p.vertical_deg)
    rows = slice(1, 17)  # 5..80 degrees: cells wholly above the disk's plane
    mean = p.candela[:-1, rows].mean(axis=0)
    error = np.sqrt(far.variance[:-1, rows].sum(axis=0)) / 36
    truth = np.cos(gamma[rows]) / np.pi
    assert np.all(np.abs(mean - truth) < 4 * error)
    assert (p.candela[:, 19:] == 0).all()  # nothing below the horizon


def test_read_and_write_ies_and_ldt(disk, tmp_path):
    ies = tmp_path / "disk.ies"
    rayconv("farfield", disk, "-o", ies)
    truth = json.loads(rayconv("info", ies, "--json"))
    p = rayset.read_photometry(ies)
    assert rayset.detect_photometry_format(ies) == "ies"
    assert p.candela.shape == (len(p.horizontal_deg), len(p.vertical_deg))
    assert p.max_candela() == pytest.approx(truth["max_intensity_cd"], rel=1e-9)
    assert p.total_flux() == pytest.approx(truth["total_flux_lm"], rel=1e-9)
    # Intensity at grid angles is the table; between them, bilinear.
    h, v = np.array([0.0, 90.0, 45.0]), np.array([0.0, 30.0, 1.25])
    i = p.intensity(h, v)
    assert i[0] == p.candela[0, 0]
    assert i[1] == p.candela[list(p.horizontal_deg).index(90), list(p.vertical_deg).index(30)]
    assert min(p.candela[9, 0], p.candela[9, 1]) <= i[2] <= max(p.candela[9, 0], p.candela[9, 1])

    # EULUMDAT records the file's name: the same name in two folders.
    (tmp_path / "py").mkdir(), (tmp_path / "cli").mkdir()
    ldt, cli = tmp_path / "py" / "disk.ldt", tmp_path / "cli" / "disk.ldt"
    rayset.write_photometry(ldt, p)
    assert rayset.detect_photometry_format(ldt) == "ldt"
    back = rayset.read_photometry(ldt)
    rayconv("convert", ies, cli)
    assert ldt.read_bytes() == cli.read_bytes()
    # EULUMDAT's C planes stop short of 360, which repeats 0.
    np.testing.assert_array_equal(back.vertical_deg, p.vertical_deg)
    np.testing.assert_array_equal(back.horizontal_deg, p.horizontal_deg[:-1])
    np.testing.assert_allclose(back.candela, p.candela[:-1], rtol=1e-3, atol=1e-3)


def test_photometry_from_arrays(tmp_path):
    p = rayset.Photometry()
    p.vertical_deg = np.arange(0, 181, 10.0)
    p.horizontal_deg = [0.0]
    p.candela = 100 * np.maximum(np.cos(np.radians(p.vertical_deg)), 0)[None, :]
    p.keywords = {"TEST": "python", "MANUFAC": "rayset"}
    out = tmp_path / "cos.ies"
    rayset.write_photometry(out, p)
    truth = json.loads(rayconv("info", out, "--json"))
    assert truth["max_intensity_cd"] == 100
    # 100 cd x cos over the upper hemisphere: 100 pi lm, to the trapezoidal rule's error.
    assert truth["total_flux_lm"] == pytest.approx(100 * np.pi, rel=5e-3)
    back = rayset.read_photometry(out)
    assert back.keywords["MANUFAC"] == "rayset"
    with pytest.raises(ValueError, match="candela"):
        p.candela = np.zeros((2, 19))
