"""The ParaView reader plugin (python/paraview/rayset_reader.py) run in pvpython, against what
rayconv and raymodel report for the same files: ray counts, totals, bounds and wavelengths of
ray files of every format rayconv writes, the largest candela and the flux of IES and EULUMDAT
files, and the lattices, spheres and diagrams of a model.

pvpython runs in a subprocess (ParaView brings its own VTK and Python): RAYSET_PVPYTHON, else
the one scripts/install-deps.sh unpacks into the build folder, else pvpython on PATH. It imports
rayset from the build's python/ folder, as python/README.md tells users to."""

import json
import os
import re
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

from conftest import BUILD, ROOT, info, rayconv, run, tool

PLUGIN = ROOT / "python" / "paraview" / "rayset_reader.py"
PROBE = Path(__file__).with_name("paraview_probe.py")
SHARED = ROOT.parent / "shared" / "data"


def find_pvpython():
    for candidate in (os.environ.get("RAYSET_PVPYTHON"), BUILD / "paraview/usr/bin/pvpython",
                      shutil.which("pvpython")):
        if candidate and Path(candidate).is_file():
            return Path(candidate)
    return None


PVPYTHON = find_pvpython()
pytestmark = pytest.mark.skipif(
    PVPYTHON is None, reason="no pvpython: scripts/install-deps.sh unpacks it into "
    "build/paraview (or set RAYSET_PVPYTHON, or install python3-paraview)")


def pv_environment(with_rayset=True):
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "PYTHONHOME")}
    if with_rayset:
        folder = BUILD / "python"
        if not (folder / "rayset").is_dir():
            pytest.fail(f"{folder}/rayset is missing: build the target _rayset")
        env["PYTHONPATH"] = str(folder)
    return env


def probe(reader, path, **properties):
    """What ParaView holds after `reader` ("open": OpenDataFile) read `path`."""
    args = [PVPYTHON, PROBE, PLUGIN, reader, path]
    args += [f"{k}={json.dumps(v)}" for k, v in properties.items()]
    result = subprocess.run([str(a) for a in args], capture_output=True, text=True,
                            env=pv_environment(), timeout=600)
    lines = [line for line in result.stdout.splitlines() if line.startswith("PROBE ")]
    if result.returncode != 0 or not lines:
        pytest.fail(f"pvpython failed ({result.returncode}):\n{result.stdout}{result.stderr}")
    return json.loads(lines[-1][len("PROBE "):])


def no_project_vtk(result):
    """ParaView's VTK only: the project's (Debian's VTK 9.1) must not be loaded alongside."""
    libraries = [Path(lib).name for lib in result["vtk_libraries"]]
    assert any(re.match(r"libvtkCommonCore-pv5\.11\.so", lib) for lib in libraries)
    assert not [lib for lib in libraries if re.match(r"libvtk\w+-9\.\d+\.so", lib)]


MM_PER_UNIT = {"mm": 1.0, "cm": 10.0, "m": 1000.0, "in": 25.4}


def check_rays(result, truth):
    """A ray cloud against rayconv info of the same file."""
    assert result["type"] == "vtkPolyData"
    n = truth["rays"]
    assert result["points"] == n and result["cells"] == n
    arrays = result["arrays"]
    assert arrays["direction"]["tuples"] == n
    assert arrays["direction"]["norm_range"][0] == pytest.approx(1, abs=2e-3)
    assert arrays["direction"]["norm_range"][1] == pytest.approx(1, abs=2e-3)
    totals = truth["rays_total"]
    for name, key in (("radiant", "radiant_W"), ("luminous", "luminous_lm")):
        if totals[key] is None:
            assert name not in arrays
        else:
            assert arrays[name]["tuples"] == n
            assert arrays[name]["sum"][0] == pytest.approx(totals[key], rel=1e-6)
    scale = MM_PER_UNIT[truth["unit"]]
    box = truth["bounding_box"]
    bounds = result["bounds"]
    for axis in range(3):
        assert bounds[2 * axis] == pytest.approx(box["min"][axis] * scale, rel=1e-6, abs=1e-9)
        assert bounds[2 * axis + 1] == pytest.approx(box["max"][axis] * scale, rel=1e-6,
                                                     abs=1e-9)
    spectral = truth["spectral"]
    if spectral.get("ray_wavelength_min_nm") is not None:
        w = arrays["wavelength"]
        assert w["tuples"] == n
        assert w["min"][0] == pytest.approx(spectral["ray_wavelength_min_nm"], rel=1e-6)
        assert w["max"][0] == pytest.approx(spectral["ray_wavelength_max_nm"], rel=1e-6)
    assert result["fields"]["unit"] == "mm"
    assert result["fields"]["rays"] == [n]


FORMATS = {"tm25": ".tm25ray", "lighttools": ".ray", "lighttools-text": ".txt",
           "zemax": ".dat", "zemax-text": ".txt", "speos": ".ray", "csv": ".csv"}


@pytest.fixture(scope="module")
def cluster_files(cluster, tmp_path_factory):
    """The cluster (a wavelength per ray) in every format rayconv writes."""
    folder = tmp_path_factory.mktemp("formats")
    files = {}
    for fmt, extension in FORMATS.items():
        path = folder / f"cluster_{fmt}{extension}"
        rayconv("convert", cluster, path, "--to", fmt)
        files[fmt] = path
    return files


@pytest.mark.parametrize("fmt", list(FORMATS))
def test_ray_file_of_each_format(fmt, cluster_files):
    path = cluster_files[fmt]
    truth = info(path)
    assert truth["format"] == fmt
    result = probe("raysetRayFileReader", path)
    assert result["proxy"] == "raysetRayFileReader"
    check_rays(result, truth)
    assert result["fields"]["format"] == fmt
    no_project_vtk(result)


def test_ray_file_in_metres_is_shown_in_mm(disk, tmp_path):
    # CSV states its unit: the same rays in m must land where they lie in mm.
    import rayset
    rays = rayset.read_rays(disk)
    metres = tmp_path / "disk_m.csv"
    rayset.write_rays(metres, {"origin": rays.origin / 1000, "direction": rays.direction,
                               "radiant": rays.radiant}, header={"unit": "m"})
    truth = info(metres)
    assert truth["unit"] == "m"
    result = probe("raysetRayFileReader", metres)
    check_rays(result, truth)
    assert result["fields"]["file_unit"] == "m"
    assert result["bounds"][1] == pytest.approx(float(rays.origin[:, 0].max()), rel=1e-5)


def test_file_dialog_picks_the_reader_by_extension(disk, tmp_path):
    # Vendors write the extension in capitals: OpenDataFile must still choose this reader.
    path = tmp_path / "DISK.TM25RAY"
    shutil.copyfile(disk, path)
    result = probe("open", path)
    assert result["proxy"] == "raysetRayFileReader"
    check_rays(result, info(path))


REAL_RAY_FILES = ["rayfile_LERTDUW_S2WP_blue_100k_20161013_IES_TM25.TM25RAY",
                  "Cyl10k.1.ray", "test_08_dat.DAT", "TestRayFiles_ZemaxWavelengthText.txt",
                  "RayFileConverter_ThreeRays_Wavelength.1.txt"]


@pytest.mark.parametrize("name", REAL_RAY_FILES)
def test_real_ray_files(name):
    path = SHARED / "rayfiles" / name
    if not path.is_file():
        pytest.skip(f"{path} is not there (the shared sample files beside the repository)")
    result = probe("raysetRayFileReader", path)
    check_rays(result, info(path))


def photometry_truth(path):
    return json.loads(rayconv("info", path, "--json"))


def check_solid(result, truth):
    assert result["type"] == "vtkPolyData"
    assert result["cells"] > 1000
    intensity = result["arrays"]["intensity"]
    # The radius toward each direction is the intensity toward it, and the stated angles are on
    # the grid: the largest radius is the file's largest candela.
    assert result["max_radius"] == pytest.approx(truth["max_intensity_cd"], rel=1e-9)
    assert intensity["max"][0] == pytest.approx(truth["max_intensity_cd"], rel=1e-9)
    # The intensity over the sphere of directions is the file's flux (the surface is the
    # table on a 5 x 2.5 degree grid: within a few per cent).
    assert intensity["integral"] == pytest.approx(truth["total_flux_lm"], rel=0.03)
    assert result["fields"]["unit"] == "cd"


@pytest.mark.parametrize("extension", ["ies", "ldt"])
def test_photometry_written_by_rayconv(extension, cluster, tmp_path):
    path = tmp_path / f"cluster.{extension}"
    rayconv("farfield", cluster, "-o", path)
    result = probe("raysetPhotometryReader", path)
    check_solid(result, photometry_truth(path))
    no_project_vtk(result)


# Symmetries: none (3.IES, 0-0-0.ldt), about C0-C180 (2.IES), about C90-C270 (0-3-0.ldt),
# quadrants (1.IES), rotational (7.IES); vertical angles over the lower half or the whole.
REAL_PHOTOMETRY = ["ABSOLUTE_LED.ies", "1.IES", "2.IES", "3.IES", "7.IES", "0-0-0.ldt",
                   "0-3-0.ldt", "4058075580602_FL_MAX_LUM_600W_757_SYM_60_WAL.ldt"]


@pytest.mark.parametrize("name", REAL_PHOTOMETRY)
def test_real_photometry(name):
    path = SHARED / "photometry" / name
    if not path.is_file():
        pytest.skip(f"{path} is not there (the shared sample files beside the repository)")
    truth = photometry_truth(path)
    result = probe("open", path)
    assert result["proxy"] == "raysetPhotometryReader"
    check_solid(result, truth)
    if truth["vertical_angles"]["max"] <= 90:
        # Light only below the horizon (gamma 0 is the nadir): the solid hangs below z = 0.
        assert result["bounds"][5] <= 1e-9 * truth["max_intensity_cd"]
        assert result["bounds"][4] < -0.1 * truth["max_intensity_cd"]


def test_type_b_photometry_is_refused_saying_why():
    path = SHARED / "photometry" / "flood_2.1.IES"
    if not path.is_file():
        pytest.skip(f"{path} is not there (the shared sample files beside the repository)")
    assert photometry_truth(path)["type"] == "B"
    result = subprocess.run([str(PVPYTHON), str(PROBE), str(PLUGIN), "raysetPhotometryReader",
                             str(path)], capture_output=True, text=True, env=pv_environment(),
                            timeout=600)
    assert "photometric type B has no C planes" in result.stdout + result.stderr


def test_finer_grid_property(tmp_path, cluster):
    path = tmp_path / "cluster.ies"
    rayconv("farfield", cluster, "-o", path)
    coarse = probe("raysetPhotometryReader", path)
    fine = probe("raysetPhotometryReader", path, CStep=2.5, GammaStep=1.25)
    assert fine["points"] > 3 * coarse["points"]
    check_solid(fine, photometry_truth(path))


@pytest.fixture(scope="module")
def model_file(cluster, tmp_path_factory):
    path = tmp_path_factory.mktemp("model") / "cluster.vdb"
    run(tool("raymodel"), "build", cluster, "-o", path, "--flux-resolution", 12,
        "--intensity-resolution", 3, "--threads", 2, "--seed", 5)
    return path


@pytest.fixture(scope="module")
def model_truth(model_file):
    return json.loads(run(tool("raymodel"), "info", model_file, "--json"))


def check_lattice(image, lattice):
    h = lattice["cell_mm"]
    assert image["type"] == "vtkImageData"
    assert image["dims"] == lattice["dims"]
    assert image["spacing"] == pytest.approx([h] * 3, rel=1e-12)
    # Points at the cell centres.
    assert image["origin"] == pytest.approx([o + h / 2 for o in lattice["origin_mm"]],
                                            rel=1e-12, abs=1e-12)


def test_model(model_file, model_truth):
    truth = model_truth
    result = probe("raysetModelReader", model_file)
    no_project_vtk(result)
    blocks = result["blocks"]
    assert list(blocks) == ["density", "flux", "spheres", "diagrams"]

    density = blocks["density"]
    check_lattice(density, truth["density_lattice"])
    assert density["arrays"]["density"]["nonzero"] == truth["density_lattice"]["occupied_cells"]
    assert density["arrays"]["density"]["sum"][0] == truth["source"]["rays"]

    flux = blocks["flux"]
    check_lattice(flux, truth["flux_lattice"])
    assert flux["arrays"]["flux"]["nonzero"] == truth["flux_lattice"]["cells_with_light"]
    assert flux["arrays"]["flux"]["sum"][0] == pytest.approx(truth["total_flux"], rel=1e-12)
    assert flux["arrays"]["luminous"]["sum"][0] == pytest.approx(truth["total_luminous_lm"],
                                                                 rel=1e-12)

    spheres = blocks["spheres"]
    assert spheres["points"] == spheres["cells"] == truth["spheres"]
    radius = spheres["arrays"]["radius"]
    assert radius["tuples"] == truth["spheres"] and radius["min"][0] > 0
    # Centres within the body's box, which the largest sphere reaches past them.
    lower, upper = truth["body_bounds_mm"]
    for axis in range(3):
        assert lower[axis] <= spheres["bounds"][2 * axis] <= upper[axis]
        assert lower[axis] <= spheres["bounds"][2 * axis + 1] <= upper[axis]
        assert spheres["bounds"][2 * axis] - radius["max"][0] <= lower[axis] + 1e-6
        assert spheres["bounds"][2 * axis + 1] + radius["max"][0] >= upper[axis] - 1e-6

    diagrams = blocks["diagrams"]["blocks"]
    assert 1 <= len(diagrams) <= truth["intensity_lattice"]["diagrams"]
    dims = truth["intensity_lattice"]["dims"]
    flux_of_diagrams = 0.0
    for name, surface in diagrams.items():
        cell = [int(c) for c in surface["fields"]["cell"]]
        assert name == "diagram_{}_{}_{}".format(*cell)
        assert all(0 <= c < d for c, d in zip(cell, dims))
        # A diagram is a density over directions times its cell's flux: the intensity over the
        # sphere is that flux (the surface is the diagram sampled every 2 x 5 degrees).
        cell_flux = surface["fields"]["cell_flux"][0]
        assert surface["arrays"]["intensity"]["integral"] == pytest.approx(cell_flux, rel=0.03)
        flux_of_diagrams += cell_flux
        # At its cell, within half a cell of its centre.
        centre = np.array(surface["fields"]["cell_centre_mm"])
        half = truth["intensity_lattice"]["cell_mm"] / 2
        b = np.array(surface["bounds"]).reshape(3, 2)
        assert (b[:, 0] >= centre - half * (1 + 1e-9)).all()
        assert (b[:, 1] <= centre + half * (1 + 1e-9)).all()
    assert flux_of_diagrams == pytest.approx(truth["total_flux"], rel=1e-9)


def test_model_diagrams_as_rayview_exports_them(model_file, model_truth):
    result = probe("raysetModelReader", model_file, DiagramsAtCells=0)
    for surface in result["blocks"]["diagrams"]["blocks"].values():
        # Centred at the origin, 1 flux unit/sr per unit of length.
        assert result and surface["max_radius"] == pytest.approx(
            surface["arrays"]["intensity"]["max"][0], rel=1e-6)
        assert surface["fields"]["length_per_intensity"] == [1.0]


@pytest.mark.skipif(not (BUILD / "viz" / "rayview").is_file(), reason="rayview is not built")
def test_model_equals_rayview_export(model_file, tmp_path):
    """rayview --export writes the model's datasets with the project's VTK: ParaView's reader
    of those files sees what the plugin makes of the model file itself."""
    folder = tmp_path / "export"
    run(tool("rayview"), model_file, "--export", folder)
    ours = probe("raysetModelReader", model_file, DiagramsAtCells=0)["blocks"]
    for name in ("density", "flux"):
        theirs = probe("open", folder / f"{name}.vti")
        assert ours[name]["dims"] == theirs["dims"]
        assert ours[name]["origin"] == pytest.approx(theirs["origin"], rel=1e-12, abs=1e-12)
        assert ours[name]["spacing"] == pytest.approx(theirs["spacing"], rel=1e-12)
        for array, entry in theirs["arrays"].items():
            assert ours[name]["arrays"][array]["sum"] == pytest.approx(entry["sum"], rel=1e-9)
            assert ours[name]["arrays"][array]["nonzero"] == entry["nonzero"]
    theirs = probe("open", folder / "spheres.vtp")
    assert ours["spheres"]["points"] == theirs["points"]
    assert ours["spheres"]["bounds"] == pytest.approx(theirs["bounds"], rel=1e-6)
    assert ours["spheres"]["arrays"]["radius"]["sum"] == pytest.approx(
        theirs["arrays"]["radius"]["sum"], rel=1e-6)
    exported = sorted(p.stem for p in folder.glob("diagram_*.vtp"))
    assert sorted(ours["diagrams"]["blocks"]) == exported
    for name in exported[:3]:  # three: each file is one more start of pvpython
        # The same directions (theta every 2, phi every 5 degrees), the poles repeated here.
        theirs = probe("open", folder / f"{name}.vtp")
        mine = ours["diagrams"]["blocks"][name]
        for key in ("min", "max"):
            assert mine["arrays"]["intensity"][key] == pytest.approx(
                theirs["arrays"]["intensity"][key], rel=1e-9)
        assert mine["bounds"] == pytest.approx(theirs["bounds"], rel=1e-9, abs=1e-15)
        assert mine["fields"]["cell_flux"] == pytest.approx(theirs["fields"]["cell_flux"],
                                                            rel=1e-12)


def test_without_rayset_the_error_says_what_to_do(disk):
    env = pv_environment(with_rayset=False)
    check = subprocess.run([str(PVPYTHON), "-c", "import rayset"], capture_output=True,
                           env=env, timeout=300)
    if check.returncode == 0:
        pytest.skip("rayset is importable in pvpython without PYTHONPATH here")
    result = subprocess.run([str(PVPYTHON), str(PROBE), str(PLUGIN), "raysetRayFileReader",
                             str(disk)], capture_output=True, text=True, env=env, timeout=300)
    assert "PYTHONPATH" in result.stdout + result.stderr
    assert "build/python" in result.stdout + result.stderr
