"""Ray files through numpy, against what rayconv reports and writes for the same files."""

import numpy as np
import pytest

import rayset
from conftest import info, rayconv


def csv_columns(path):
    """A rayset CSV file (docs/formats/csv.md) parsed by numpy alone: {column: values}."""
    with open(path) as f:
        lines = [line for line in f if not line.startswith("#") and line.strip()]
    names = lines[0].strip().split(",")
    values = np.loadtxt(lines[1:], delimiter=",", dtype=np.float64, ndmin=2)
    return {name: values[:, i] for i, name in enumerate(names)}


def test_count_and_flux_equal_rayconv_info(disk):
    rays = rayset.read_rays(disk)
    truth = info(disk)
    assert len(rays) == truth["rays"] == 20000
    assert rays.header["ray_count"] == 20000
    assert rays.totals["rays"] == 20000
    assert rays.totals["radiant"] == pytest.approx(truth["rays_total"]["radiant_W"], rel=1e-12)
    assert rays.radiant_total == pytest.approx(truth["rays_total"]["radiant_W"], rel=1e-12)
    assert rays.header["stated_radiant"] == truth["header"]["radiant_W"] == 1.0
    assert rays.header["unit"] == truth["unit"] == "mm"
    assert rays.header["format"] == "tm25"
    assert rays.header["spectral"] == "single_wavelength"
    assert rays.header["single_wavelength"] == truth["spectral"]["single_wavelength_nm"]
    assert rays.header["text"][0] == truth["text"]["name"]
    lower, upper = rays.origin.min(axis=0), rays.origin.max(axis=0)
    np.testing.assert_array_equal(lower, np.float32(truth["bounding_box"]["min"]))
    np.testing.assert_array_equal(upper, np.float32(truth["bounding_box"]["max"]))


def test_columns_and_missing_values(disk, cluster):
    rays = rayset.read_rays(disk)
    assert rays.origin.shape == rays.direction.shape == (20000, 3)
    assert rays.origin.dtype == np.float32 and rays.spectrum.dtype == np.int32
    # The disk file carries radiant flux only and one wavelength for all rays (in the header).
    assert np.isnan(rays.luminous).all() and np.isnan(rays.wavelength).all()
    assert (rays.spectrum == -1).all() and rays.extra.shape == (20000, 0)
    np.testing.assert_allclose(np.linalg.norm(rays.direction, axis=1), 1, atol=1e-6)
    assert (rays.origin[:, 2] == 0).all() and (rays.direction[:, 2] > 0).all()

    c = rayset.read_rays(cluster)
    truth = info(cluster)
    assert c.header["spectral"] == "per_ray_wavelength"
    assert set(np.unique(c.wavelength)) == {630, 530, 460}
    assert np.isnan(c.luminous).all() and truth["rays_total"]["luminous_lm"] is None
    assert c.radiant_total == pytest.approx(truth["rays_total"]["radiant_W"], rel=1e-12)


@pytest.mark.parametrize("source", ["disk", "cluster"])
def test_values_equal_rayconv_csv(source, request, tmp_path):
    path = request.getfixturevalue(source)
    csv = tmp_path / "rays.csv"
    rayconv("convert", path, csv)
    truth = csv_columns(csv)
    rays = rayset.read_rays(path)
    for i, axis in enumerate("xyz"):
        np.testing.assert_array_equal(rays.origin[:, i], truth[axis].astype(np.float32))
        np.testing.assert_array_equal(rays.direction[:, i], truth["k" + axis].astype(np.float32))
    np.testing.assert_array_equal(rays.radiant, truth["radiant_W"].astype(np.float32))
    if "luminous_lm" in truth:
        np.testing.assert_array_equal(rays.luminous, truth["luminous_lm"].astype(np.float32))
    if "wavelength_nm" in truth:
        np.testing.assert_array_equal(rays.wavelength, truth["wavelength_nm"].astype(np.float32))


@pytest.mark.parametrize("fmt", ["tm25", "lighttools", "lighttools-text", "zemax", "zemax-text",
                                 "speos", "csv"])
def test_write_then_read_back(fmt, cluster, tmp_path):
    rays = rayset.read_rays(cluster)
    out = tmp_path / f"rays.{fmt}"
    rayset.write_rays(out, rays, format=fmt)
    assert rayset.detect_ray_format(out) == fmt
    back = rayset.read_rays(out)
    assert len(back) == len(rays)
    np.testing.assert_array_equal(back.origin, rays.origin)
    np.testing.assert_array_equal(back.direction, rays.direction)
    np.testing.assert_array_equal(back.radiant, rays.radiant)
    # Zemax stores wavelengths in micrometres: exact to one float32 rounding.
    np.testing.assert_allclose(back.wavelength, rays.wavelength, rtol=1.2e-7)
    assert back.totals["radiant"] == pytest.approx(rays.totals["radiant"], rel=1e-12)


def test_written_file_equals_rayconv_convert(cluster, tmp_path):
    """The same header and rays written by Python and by rayconv give the same bytes."""
    for fmt, name in (("tm25", "a.tm25ray"), ("zemax", "a.dat"), ("csv", "a.csv")):
        ours, theirs = tmp_path / ("py_" + name), tmp_path / ("cli_" + name)
        rayset.write_rays(ours, rayset.read_rays(cluster))
        rayconv("convert", cluster, theirs)
        assert ours.read_bytes() == theirs.read_bytes(), fmt


def test_arrays_from_scratch(tmp_path):
    rng = np.random.default_rng(5)
    n = 1000
    direction = rng.normal(size=(n, 3))
    direction[:, 2] = np.abs(direction[:, 2])
    direction /= np.linalg.norm(direction, axis=1, keepdims=True)
    arrays = {"origin": rng.uniform(-1, 1, (n, 3)), "direction": direction,
              "radiant": np.full(n, 0.002)}
    out = tmp_path / "new.tm25ray"
    rayset.write_rays(out, arrays, header={"unit": "mm", "stated_radiant": 2.0})
    truth = info(out)
    assert truth["rays"] == n
    assert truth["header"]["radiant_W"] == 2.0
    assert truth["rays_total"]["radiant_W"] == pytest.approx(2.0, rel=1e-6)
    back = rayset.read_rays(out)
    np.testing.assert_array_equal(back.origin, arrays["origin"].astype(np.float32))
    assert np.isnan(back.luminous).all()


def test_chunks_equal_whole_file(cluster):
    whole = rayset.read_rays(cluster)
    with rayset.RayReader(cluster) as reader:
        assert len(reader) == 30000
        chunks = list(reader.chunks(7001))
        totals = reader.totals
    assert [len(c) for c in chunks] == [7001] * 4 + [30000 - 4 * 7001]
    assert [c.first_index for c in chunks] == [0, 7001, 14002, 21003, 28004]
    for name in ("origin", "direction", "radiant", "luminous", "wavelength", "spectrum"):
        np.testing.assert_array_equal(np.concatenate([getattr(c, name) for c in chunks]),
                                      getattr(whole, name), err_msg=name)
    assert totals["rays"] == 30000
    assert totals["radiant"] == pytest.approx(whole.totals["radiant"], rel=1e-12)


def test_streamed_conversion(cluster, tmp_path):
    out = tmp_path / "streamed.dat"
    reader = rayset.RayReader(cluster)
    with rayset.RayWriter(out, header=reader.header) as writer:
        for rays in reader.chunks(4096):
            writer.write(rays)
    np.testing.assert_array_equal(rayset.read_rays(out).origin, rayset.read_rays(cluster).origin)


def test_errors_name_file_and_offset(disk, tmp_path):
    truncated = tmp_path / "truncated.tm25ray"
    data = disk.read_bytes()
    truncated.write_bytes(data[: len(data) - 1000])
    with pytest.raises(rayset.Error) as e:
        rayset.read_rays(truncated)
    assert str(truncated) in str(e.value)

    bad = tmp_path / "bad.csv"
    bad.write_text("x,y,z,kx,ky,kz,radiant_W\n0,0,0,0,0,1,1\n0,0,0,0,0,2,1\n")
    with pytest.raises(rayset.Error, match=r"bad\.csv.*3") as e:
        rayset.read_rays(bad)
    assert isinstance(e.value, RuntimeError)

    # A NaN direction deep in a binary file: the message gives the ray's byte offset.
    rays = rayset.read_rays(disk)
    rays.direction[12345] = np.nan
    broken = tmp_path / "nan.tm25ray"
    rayset.write_rays(broken, rays)
    with pytest.raises(rayset.Error, match=r"nan\.tm25ray: byte \d+"):
        rayset.read_rays(broken)
    with pytest.raises(rayset.Error, match="byte"):
        for _ in rayset.RayReader(broken).chunks(1000):
            pass

    with pytest.raises(rayset.Error, match="missing"):
        rayset.read_rays(tmp_path / "missing.tm25ray")
    with pytest.raises(ValueError, match="format"):
        rayset.write_rays(tmp_path / "x.ray", rays)
