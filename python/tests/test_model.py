"""Models built, saved and queried from Python, against raymodel's build of the same file, the
ray file's flux, and Monte Carlo estimates of the densities the emitter interface returns."""

import json

import numpy as np
import pytest

import rayset
from conftest import info, run, tool

OPTIONS = dict(flux_resolution=16, threads=2, seed=3)


@pytest.fixture(scope="module")
def model(disk):
    return rayset.Model.build(disk, **OPTIONS)


def uniform(seed, rows, columns):
    return np.random.default_rng(seed).random((rows, columns))


def test_flux_equals_ray_file(model, disk):
    truth = info(disk)["rays_total"]["radiant_W"]
    assert model.info()["flux_unit"] == "W"
    assert model.phi() == pytest.approx(truth, rel=1e-9)
    assert model.info()["source"]["rays"] == 20000
    assert model.phi("luminous") == pytest.approx(683.002 * truth, rel=1e-4)  # all at 555 nm


def test_equals_raymodel_build(model, disk, tmp_path):
    vdb = tmp_path / "cli.vdb"
    summary = json.loads(run(tool("raymodel"), "build", disk, "-o", vdb, "--flux-resolution", 16,
                             "--threads", 2, "--seed", 3, "--json"))
    assert model.phi() == summary["total_flux"]
    theirs = rayset.Model.load(vdb)
    # The file keeps some values in single precision (visible fractions): compare models as read.
    ours = tmp_path / "py.vdb"
    model.save(ours)
    ours = rayset.Model.load(ours)
    assert theirs.info()["spheres"] == ours.info()["spheres"] == model.info()["spheres"]
    np.testing.assert_array_equal(theirs.spheres(), ours.spheres())
    u = uniform(1, 2000, 7)
    a, b = ours.sample_Le(u), theirs.sample_Le(u)
    for key in a:
        np.testing.assert_array_equal(a[key], b[key], err_msg=key)


def test_save_and_load(model, tmp_path):
    path = tmp_path / "model.vdb"
    model.save(path)
    back = rayset.Model.load(path)
    assert back.phi() == model.phi()
    # The file holds the spheres' centres as OpenVDB point positions (float32 offsets within
    # voxels), a rounding of their own: the body moves by an ulp or so, nothing else changes.
    np.testing.assert_allclose(back.bounds, model.bounds, rtol=1e-6)
    order = lambda s: s[np.lexsort(s.T)]  # noqa: E731
    np.testing.assert_allclose(order(back.spheres()), order(model.spheres()), atol=1e-6)
    ref = np.tile([0.3, -0.2, 8.0], (500, 1))
    u = uniform(2, 500, 5)
    a, b = model.sample_Li(ref, u), back.sample_Li(ref, u)
    for key in ("valid", "wi", "pdf"):
        np.testing.assert_array_equal(a[key], b[key], err_msg=key)
    for key in ("distance", "Li", "colour"):
        np.testing.assert_allclose(a[key], b[key], rtol=1e-6, err_msg=key)
    with pytest.raises(rayset.Error, match="nothing.vdb"):
        rayset.Model.load(tmp_path / "nothing.vdb")


def test_pdf_Li_integrates_to_one(model):
    """pdf_Li is a density over directions: 1 = integral of pdf_Li(ref, w) dw, estimated with
    directions drawn uniformly (numpy) in a cone around the source that holds its body."""
    ref = np.array([0.5, 0.0, 6.0])
    lower, upper = (np.array(b) for b in model.bounds)
    corners = np.array([[x, y, z] for x in (lower[0], upper[0]) for y in (lower[1], upper[1])
                        for z in (lower[2], upper[2])]) - ref
    axis = -ref / np.linalg.norm(ref)
    cos_max = (corners @ axis / np.linalg.norm(corners, axis=1)).min() - 0.01
    n = 400000
    rng = np.random.default_rng(9)
    cos_t = 1 - rng.random(n) * (1 - cos_max)
    phi = 2 * np.pi * rng.random(n)
    sin_t = np.sqrt(1 - cos_t ** 2)
    t1 = np.cross(axis, [1.0, 0, 0])
    t1 /= np.linalg.norm(t1)
    t2 = np.cross(axis, t1)
    w = (sin_t * np.cos(phi))[:, None] * t1 + (sin_t * np.sin(phi))[:, None] * t2 \
        + cos_t[:, None] * axis
    cone = 2 * np.pi * (1 - cos_max)
    pdf = model.pdf_Li(np.tile(ref, (n, 1)), w)
    estimate = cone * pdf.mean()
    error = cone * pdf.std() / np.sqrt(n)
    assert abs(estimate - 1) < 4 * error + 1e-3, (estimate, error)


def test_sample_Li_agrees_with_pdf_Li(model):
    ref = np.tile([0.5, 0.0, 6.0], (5000, 1))
    s = model.sample_Li(ref, uniform(4, 5000, 5))
    # A point drawn in the emitting volume whose direction misses the body gives no sample
    # (light counts only where a camera would see the body, complex_source.cpp).
    assert s["valid"].mean() > 0.95
    assert (s["pdf"][~s["valid"]] == 0).all()
    s = {key: value[s["valid"]] for key, value in s.items()}
    ref = ref[: len(s["wi"])]
    np.testing.assert_allclose(np.linalg.norm(s["wi"], axis=1), 1, rtol=1e-12)
    assert (s["pdf"] > 0).all() and (s["Li"] >= 0).all()
    np.testing.assert_allclose(model.pdf_Li(ref, s["wi"]), s["pdf"], rtol=1e-6)
    # Irradiance 6 mm above a Lambertian disk of radius 1 mm and 1 W (radiance 1/pi^2 W/(mm^2
    # sr)): pi L r^2 / (r^2 + h^2) on its axis; the point is 0.5 mm off it (a 1% change).
    e = np.sum(s["Li"] * np.maximum(0, -s["wi"][:, 2]) / s["pdf"]) / 5000
    assert e == pytest.approx(np.pi / np.pi ** 2 / 37, rel=0.05)


def test_sample_Le_mean_flux_and_densities(model):
    n = 100000
    s = model.sample_Le(uniform(5, n, 7))
    assert s["origin"].shape == s["direction"].shape == (n, 3)
    mean, error = s["flux"].mean(), s["flux"].std() / np.sqrt(n)
    assert abs(mean - model.phi()) < 4 * error + 1e-12
    position, direction = model.pdf_Le(s["origin"][:1000], s["direction"][:1000])
    np.testing.assert_allclose(position, s["pdf_position"][:1000], rtol=1e-9)
    np.testing.assert_allclose(direction, s["pdf_direction"][:1000], rtol=1e-9)
    # The disk emits upward; the smoothed diagrams leak a little below the horizon.
    assert (s["direction"][:, 2] > 0).mean() > 0.99


def test_radiance_seen_from_above(model):
    origin = np.tile([0.0, 0.0, 10.0], (3, 1))
    direction = np.array([[0, 0, -1.0], [0.05, 0, -1], [1.0, 0, 0]])
    direction /= np.linalg.norm(direction, axis=1, keepdims=True)
    r = model.L(origin, direction)
    assert list(r["hit"]) == [True, True, False]
    assert r["L"][2] == 0 and (r["L"][:2] > 0).all()
    hit = model.intersect(origin, direction)
    assert hit["t"][0] == pytest.approx(10 - hit["point"][0][2])
    with pytest.raises(ValueError, match="rows"):
        model.pdf_Li(origin, direction[:2])


def test_queries_refuse_values_they_cannot_use(model):
    """Non-finite points, zero directions and numbers outside [0, 1] are refused with the row,
    before they reach Embree (which asserts on a ray that is not finite and ends the process)."""
    good, zero = np.array([[0.0, 0.0, 10.0]]), np.zeros((1, 3))
    with pytest.raises(ValueError, match="direction: row 0 is zero"):
        model.L(good, zero)
    with pytest.raises(ValueError, match="direction: row 1 holds nan"):
        model.intersect(np.repeat(good, 2, axis=0), np.array([[0, 0, -1.0], [0, np.nan, 1]]))
    with pytest.raises(ValueError, match="ref: row 0 holds inf"):
        model.pdf_Li(np.array([[np.inf, 0, 0]]), np.array([[0, 0, -1.0]]))
    with pytest.raises(ValueError, match=r"u: row 0 holds 1.5 \(uniform numbers lie in \[0, 1\]\)"):
        model.sample_Li(good, np.array([[0.5, 0.5, 1.5, 0.5, 0.5]]))
    with pytest.raises(ValueError, match="u: row 0 holds nan"):
        model.sample_Le(np.array([[0.5] * 6 + [np.nan]]))


@pytest.fixture(scope="module")
def cluster_model(cluster, tmp_path_factory):
    """The cluster's model as raymodel builds it, with raymodel info's summary of it."""
    path = tmp_path_factory.mktemp("lattices") / "cluster.vdb"
    run(tool("raymodel"), "build", cluster, "-o", path, "--flux-resolution", 12,
        "--intensity-resolution", 3, "--threads", 2, "--seed", 5)
    summary = json.loads(run(tool("raymodel"), "info", path, "--json"))
    return rayset.Model.load(path), summary


def test_lattices_against_raymodel_info(cluster_model):
    model, truth = cluster_model
    for name in ("density", "flux", "intensity"):
        lattice, frame = model.lattice(name), truth[f"{name}_lattice"]
        assert list(lattice["dims"]) == frame["dims"]
        assert list(lattice["origin"]) == frame["origin_mm"]
        assert lattice["cell_size"] == frame["cell_mm"]
        assert lattice["resolution"] == frame["resolution"]
    dims = tuple(reversed(truth["density_lattice"]["dims"]))  # arrays are [z, y, x]
    density = model.lattice("density")["density"]
    assert density.shape == dims
    assert np.count_nonzero(density) == truth["density_lattice"]["occupied_cells"]
    assert density.sum(dtype=np.float64) == truth["source"]["rays"]
    flux = model.lattice("flux")
    assert np.count_nonzero(flux["flux"]) == truth["flux_lattice"]["cells_with_light"]
    assert flux["flux"].sum() == pytest.approx(truth["total_flux"], rel=1e-12)
    assert flux["luminous"].sum() == pytest.approx(truth["total_luminous_lm"], rel=1e-12)
    # Every cell with light draws its directions from a diagram; cells without have none.
    assert ((flux["diagram"] >= 0) == (flux["flux"] > 0)).all()
    intensity = model.lattice("intensity")["diagram"]
    assert sorted(intensity[intensity >= 0]) == list(range(truth["intensity_lattice"]["diagrams"]))
    with pytest.raises(ValueError, match="density"):
        model.lattice("voxels")


def test_diagrams_sum_to_the_far_field(cluster_model):
    model, truth = cluster_model
    d = model.diagrams()
    k = truth["intensity_lattice"]["diagrams"]
    assert d["cell"].shape == d["centre"].shape == (k, 3) and d["flux"].shape == (k,)
    assert d["flux"].sum() == pytest.approx(truth["total_flux"], rel=1e-12)
    frame = truth["intensity_lattice"]
    np.testing.assert_allclose(
        d["centre"], np.array(frame["origin_mm"]) + (d["cell"] + 0.5) * frame["cell_mm"],
        rtol=1e-12, atol=1e-12)
    intensity = model.lattice("intensity")["diagram"]
    for i, (x, y, z) in enumerate(d["cell"]):
        assert intensity[z, y, x] == i
    # The source's far field (the emitter interface) is the sum of its cells' diagrams, and
    # each diagram's intensity over the sphere is its cell's flux (Monte Carlo, uniform w).
    n = 200000
    w = np.random.default_rng(3).normal(size=(n, 3))
    w /= np.linalg.norm(w, axis=1, keepdims=True)
    each = np.array([model.diagram_intensity(i, w) for i in range(k)])
    np.testing.assert_allclose(each.sum(axis=0), model.intensity(w), rtol=1e-12, atol=1e-15)
    estimate = 4 * np.pi * each.mean(axis=1)
    error = 4 * np.pi * each.std(axis=1) / np.sqrt(n)
    assert (np.abs(estimate - d["flux"]) < 4 * error).all(), (estimate, d["flux"], error)
    with pytest.raises(IndexError):
        model.diagram_intensity(k, w[:1])
