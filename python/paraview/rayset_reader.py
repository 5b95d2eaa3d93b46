"""rayset's readers for ParaView: ray files, IES / EULUMDAT photometry and light-source models.

One Python plugin file for ParaView 5.11 (Debian 12's `paraview`). It reads every file with the
Python module `rayset` (this repository's python/), so ParaView shows the values the rayset tools
(rayconv, raymodel, rayview) compute from the same file, and builds the VTK data with ParaView's
own VTK: nothing of the project's VTK is loaded.

Making `rayset` importable in ParaView
    ParaView runs Debian's /usr/bin/python3 (3.11) and puts its own folders first on sys.path.
    Point PYTHONPATH at the folder holding the package `rayset`: a CMake build of this
    repository makes it in BUILD/python (the module `_rayset` next to rayset/__init__.py), and it
    holds nothing else, so ParaView keeps Debian's numpy (python3-numpy):

        cmake --build build -j2 --target _rayset
        PYTHONPATH=/path/to/rayset/build/python build/paraview/usr/bin/pvpython ...

    Any CPython 3.11 build of the module works (scripts/install-deps.sh builds it for the
    3.11 of build/venv). Without it, opening a file fails with a message that says this.

Getting ParaView with its Python
    Debian 12's python3-paraview (pvpython, and the GUI's Python) conflicts with python3-vtk9,
    which the project's build needs (libvtk9-dev). scripts/install-deps.sh therefore installs
    `paraview` and unpacks python3-paraview into build/paraview: build/paraview/usr/bin/pvpython,
    and build/paraview/usr/bin/paraview, the GUI with that Python. It also mends the unpacked
    ParaView 5.11.0, whose loader of Python plugins imports inspect.getargspec, gone from Python
    3.11. With Debian's own python3-paraview (on a machine without libvtk9-dev) no Python plugin
    loads until that name exists: run `import inspect; inspect.getargspec =
    inspect.getfullargspec` first (in pvpython, or in the GUI's View > Python Shell).

Loading the plugin
    GUI: start it with PYTHONPATH set as above, then Tools > Manage Plugins > Load New... > this
    file (tick "Auto Load" to have it at every start). File > Open then offers the readers below
    for their extensions (and asks which reader where ParaView has one too, as for .csv).
    pvpython:

        from paraview.simple import *
        LoadPlugin("/path/to/rayset_reader.py", ns=globals())
        rays = raysetRayFileReader(FileName="LED.TM25RAY")   # or OpenDataFile("LED.TM25RAY")
        Show(rays); Render()

    (`ns` must be a namespace that already holds names, as globals() does: LoadPlugin takes an
    empty dict for none.)

What each file becomes
    Ray files (.tm25ray TM-25, .ray LightTools / SPEOS, .txt LightTools / Zemax text, .dat .sdf
    Zemax, .csv; the format is told from the content as rayconv does): "rayset Ray File Reader",
    a vtkPolyData of one vertex per ray at its origin, in mm whatever unit the file uses. Point
    data: "direction" (unit vectors, 3 components), "radiant" (W) when the file carries radiant
    flux, "luminous" (lm) when it carries luminous flux, "wavelength" (nm) when the file gives
    one per ray or one for all, "spectrum" (index into the file's spectral tables) when it has
    tables, and the file's extra columns (TM-25 Stokes parameters, tristimulus...) by name.
    Field data: "format", "unit" (mm), "file_unit", "rays", "radiant_total" (W),
    "luminous_total" (lm). For a file larger than memory, rayconv's sampling first.

    Photometry (.ies IES LM-63, .ldt EULUMDAT, type C): "rayset Photometry Reader", the
    photometric solid as `rayview --show solid` draws it: a closed surface whose distance from
    the centre toward each direction is the intensity toward it (1 cd = 1 unit of length), gamma
    0 (nadir) along -z. Point data "intensity" (cd) and normals; field data "unit" (cd),
    "max_candela", "total_flux" (lm). The grid is C every "C Step" and gamma every "Gamma Step"
    degrees joined with every angle the file states (its symmetry unfolded), so the stated values
    are on the surface: its largest radius is the file's largest candela.

    Light-source models (.vdb files of `raymodel build`): "rayset Model Reader", a
    vtkMultiBlockDataSet of
      "density"   vtkImageData: the density lattice, one point per voxel centre, point data
                  "density" (rays per voxel, 0 where empty), as `rayview --export` writes it;
      "flux"      vtkImageData: the flux lattice, point data "flux" (the model's flux unit),
                  "luminous" (lm), "diagram" (index of the cell's goniometric diagram, -1 for
                  none);
      "spheres"   vtkPolyData: one vertex per sphere of the body at its centre (mm), point data
                  "radius" (mm): show it as Point Gaussian with "Scale by Array" on radius and
                  "Gaussian Radius" 1 to see the spheres;
      "diagrams"  vtkMultiBlockDataSet of the goniometric diagrams that emit, one polar surface
                  each ("diagram_i_j_k", the intensity cell), point data "intensity" (flux
                  unit/sr), field data "cell", "cell_centre_mm", "cell_flux", "unit",
                  "surface_centre_mm", "length_per_intensity" (mm per flux unit/sr). With
                  "Diagrams At Cells" (default) each surface sits at its cell's centre, scaled so
                  that the largest intensity of all reaches half a cell; off, they are centred at
                  the origin with 1 flux unit/sr = 1 unit of length, as `rayview --export`
                  writes them.
"""

import math
import os

import numpy as np
from paraview.util.vtkAlgorithm import smdomain, smhint, smproperty, smproxy
from vtkmodules.util import numpy_support
from vtkmodules.util.vtkAlgorithm import VTKPythonAlgorithmBase
from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints, vtkStringArray
from vtkmodules.vtkCommonDataModel import (
    vtkCellArray,
    vtkCompositeDataSet,
    vtkImageData,
    vtkMultiBlockDataSet,
    vtkPolyData,
)
from vtkmodules.vtkFiltersCore import vtkPolyDataNormals

paraview_plugin_name = "rayset readers"
paraview_plugin_version = "0.1"

RAY_EXTENSIONS = "tm25ray TM25RAY ray RAY txt TXT dat DAT sdf SDF csv CSV"
PHOTOMETRY_EXTENSIONS = "ies IES ldt LDT"
MODEL_EXTENSIONS = "vdb VDB"

_MM_PER_UNIT = {"mm": 1.0, "cm": 10.0, "m": 1000.0, "in": 25.4, "ft": 304.8, "um": 1e-3,
                "nm": 1e-6}


def _rayset():
    """The module rayset, or an ImportError that says how to make it importable here."""
    try:
        import rayset
    except ImportError as error:
        raise ImportError(
            "rayset_reader: the Python module 'rayset' cannot be imported in ParaView's Python "
            f"({error}). Start ParaView / pvpython with PYTHONPATH naming the folder that holds "
            "the package rayset, e.g. PYTHONPATH=/path/to/rayset/build/python after "
            "`cmake --build build --target _rayset` (see python/README.md, 'ParaView')."
        ) from error
    return rayset


# ---- VTK data from numpy arrays ----------------------------------------------------------------


def _array(values, name):
    """A VTK array holding a copy of `values` (numpy_support keeps no reference of its own)."""
    array = numpy_support.numpy_to_vtk(np.ascontiguousarray(values), deep=True)
    array.SetName(name)
    return array


def _field(data, name, values):
    if isinstance(values, str):
        array = vtkStringArray()
        array.SetName(name)
        array.InsertNextValue(values)
    else:
        array = vtkDoubleArray()
        array.SetName(name)
        for value in np.atleast_1d(np.asarray(values, dtype=np.float64)):
            array.InsertNextValue(value)
    data.GetFieldData().AddArray(array)


def _points(xyz):
    points = vtkPoints()
    points.SetData(_array(np.asarray(xyz).reshape(-1, 3), "points"))
    return points


def _cells(counts_and_ids):
    """A vtkCellArray of cells given as (offsets, connectivity) arrays."""
    offsets, connectivity = counts_and_ids
    cells = vtkCellArray()
    cells.SetData(numpy_support.numpy_to_vtkIdTypeArray(np.ascontiguousarray(offsets), deep=True),
                  numpy_support.numpy_to_vtkIdTypeArray(np.ascontiguousarray(connectivity),
                                                        deep=True))
    return cells


def _vertices(n):
    """One vertex cell per point."""
    ids = np.arange(n + 1, dtype=numpy_support.ID_TYPE_CODE)
    return _cells((ids, ids[:-1]))


def _grid_surface(rings, sectors):
    """Quads of a (sectors x rings) grid of points, rows of constant sector, closed around."""
    i, j = np.meshgrid(np.arange(sectors), np.arange(rings - 1), indexing="ij")
    nxt = (i + 1) % sectors
    quads = np.stack([i * rings + j, nxt * rings + j, nxt * rings + j + 1, i * rings + j + 1],
                     axis=-1).reshape(-1, 4).astype(numpy_support.ID_TYPE_CODE)
    offsets = np.arange(len(quads) + 1, dtype=numpy_support.ID_TYPE_CODE) * 4
    return _cells((offsets, quads.ravel()))


def _with_normals(surface):
    normals = vtkPolyDataNormals()
    normals.SetInputData(surface)
    normals.SplittingOff()
    normals.ConsistencyOn()
    normals.AutoOrientNormalsOff()
    normals.Update()
    out = vtkPolyData()
    out.ShallowCopy(normals.GetOutput())
    return out


def _name_block(blocks, index, name, data):
    blocks.SetBlock(index, data)
    blocks.GetMetaData(index).Set(vtkCompositeDataSet.NAME(), name)


# ---- What each kind of file becomes -----------------------------------------------------------


def ray_cloud(path):
    """A ray file as a vtkPolyData of vertices at the origins (mm) with the rays' values."""
    rays = _rayset().read_rays(path)
    header = rays.header
    n = len(rays)
    unit = header.get("unit", "mm")
    scale = _MM_PER_UNIT.get(unit)
    if scale is None:
        raise ValueError(f"{path}: unknown length unit '{unit}'")
    cloud = vtkPolyData()
    origin = rays.origin if scale == 1 else rays.origin.astype(np.float64) * scale
    cloud.SetPoints(_points(origin))
    cloud.SetVerts(_vertices(n))
    data = cloud.GetPointData()
    direction = _array(rays.direction, "direction")
    data.AddArray(direction)
    data.SetVectors(direction)
    if header.get("has_radiant"):
        data.AddArray(_array(rays.radiant, "radiant"))
    if header.get("has_luminous"):
        data.AddArray(_array(rays.luminous, "luminous"))
    data.SetActiveScalars("radiant" if header.get("has_radiant") else "luminous")
    spectral = header.get("spectral")
    if spectral == "per_ray_wavelength":
        data.AddArray(_array(rays.wavelength, "wavelength"))
    elif spectral == "single_wavelength":
        data.AddArray(_array(np.full(n, header["single_wavelength"], np.float32), "wavelength"))
    elif spectral in ("shared_table", "per_ray_table"):
        data.AddArray(_array(rays.spectrum, "spectrum"))
    for k, (kind, label) in enumerate(header.get("extras", ())):
        data.AddArray(_array(rays.extra[:, k], label or kind))
    _field(cloud, "format", str(header.get("format", "")))
    _field(cloud, "unit", "mm")
    _field(cloud, "file_unit", unit)
    _field(cloud, "rays", n)
    _field(cloud, "radiant_total", rays.radiant_total if header.get("has_radiant") else math.nan)
    _field(cloud, "luminous_total",
           rays.luminous_total if header.get("has_luminous") else math.nan)
    return cloud


def _stated_angles(photometry):
    """The file's horizontal angles unfolded over 0..360 by the symmetry its range implies."""
    h = np.asarray(photometry.horizontal_deg, dtype=np.float64)
    c = np.concatenate([h, 360 - h, 180 - h, 180 + h])
    return c[(c >= 0) & (c < 360)]


def photometric_solid(path, c_step=5.0, gamma_step=2.5):
    """An IES / EULUMDAT file's photometric solid (cd; gamma 0 along -z) as a vtkPolyData."""
    photometry = _rayset().read_photometry(path)
    if photometry.type != "C":
        raise ValueError(f"{path}: photometric type {photometry.type} has no C planes; the "
                         "photometric solid is drawn for type C photometry only")
    if not (c_step > 0 and gamma_step > 0):
        raise ValueError("C Step and Gamma Step must be above 0 degrees")
    nc = max(3, round(360 / c_step))
    ng = max(2, round(180 / gamma_step))
    # Joined with the stated angles, so that the stated values are on the surface: between
    # grid angles the intensity is bilinear, so its largest value is the largest stated.
    cs = np.unique(np.round(np.concatenate(
        [np.arange(nc) * 360.0 / nc, _stated_angles(photometry)]), 9))
    gs = np.unique(np.round(np.concatenate(
        [np.arange(ng + 1) * 180.0 / ng, np.asarray(photometry.vertical_deg, np.float64)]), 9))
    gs = gs[(gs >= 0) & (gs <= 180)]
    c, g = np.meshgrid(cs, gs, indexing="ij")  # rows of constant C: the poles repeat per C
    intensity = photometry.intensity(c.ravel(), g.ravel())
    cr, gr = np.radians(c.ravel()), np.radians(g.ravel())
    xyz = np.stack([intensity * np.sin(gr) * np.cos(cr), intensity * np.sin(gr) * np.sin(cr),
                    -intensity * np.cos(gr)], axis=-1)
    solid = vtkPolyData()
    solid.SetPoints(_points(xyz))
    solid.SetPolys(_grid_surface(len(gs), len(cs)))
    solid.GetPointData().SetScalars(_array(intensity, "intensity"))
    _field(solid, "unit", "cd")
    _field(solid, "source", os.path.basename(path))
    _field(solid, "max_candela", photometry.max_candela())
    _field(solid, "total_flux", photometry.total_flux())
    return _with_normals(solid)


def _lattice_image(lattice, arrays):
    """A lattice as rayview exports it: one point per cell centre, point data per cell."""
    image = vtkImageData()
    image.SetDimensions(*lattice["dims"])
    h = lattice["cell_size"]
    image.SetOrigin(*(o + 0.5 * h for o in lattice["origin"]))
    image.SetSpacing(h, h, h)
    for k, name in enumerate(arrays):
        array = _array(np.asarray(lattice[name]).ravel(), name)  # [z, y, x]: VTK's order
        if k == 0:
            image.GetPointData().SetScalars(array)
        else:
            image.GetPointData().AddArray(array)
    return image


def _sphere_directions(rings, sectors):
    """Unit directions of a polar grid: rows of constant phi, theta 0..pi (poles repeated)."""
    theta = np.pi * np.arange(rings + 1) / rings
    phi = 2 * np.pi * np.arange(sectors) / sectors
    p, t = np.meshgrid(phi, theta, indexing="ij")
    return np.stack([np.sin(t) * np.cos(p), np.sin(t) * np.sin(p), np.cos(t)],
                    axis=-1).reshape(-1, 3)


def diagram_surfaces(model, at_cells=True, rings=90, sectors=72):
    """The goniometric diagrams that emit, one polar surface each, as a vtkMultiBlockDataSet."""
    diagrams = model.diagrams()
    info = model.info()
    unit = info["flux_unit"] + "/sr"
    directions = _sphere_directions(rings, sectors)
    emitting = [k for k in range(len(diagrams["empty"])) if not diagrams["empty"][k]]
    values = {k: model.diagram_intensity(k, directions) for k in emitting}
    scale = 1.0
    if at_cells and values:
        largest = max(float(v.max()) for v in values.values())
        cell = model.lattice("intensity")["cell_size"]
        scale = 0.5 * cell / largest if largest > 0 else 1.0
    blocks = vtkMultiBlockDataSet()
    for index, k in enumerate(emitting):
        intensity = values[k]
        centre = diagrams["centre"][k]
        xyz = directions * (scale * intensity)[:, None]
        if at_cells:
            xyz = xyz + centre
        surface = vtkPolyData()
        surface.SetPoints(_points(xyz))
        surface.SetPolys(_grid_surface(rings + 1, sectors))
        surface.GetPointData().SetScalars(_array(intensity, "intensity"))
        cell = [int(a) for a in diagrams["cell"][k]]
        _field(surface, "cell", cell)
        _field(surface, "cell_centre_mm", centre)
        _field(surface, "cell_flux", diagrams["flux"][k])
        _field(surface, "unit", unit)
        _field(surface, "length_per_intensity", scale)
        _field(surface, "surface_centre_mm", centre if at_cells else np.zeros(3))
        _name_block(blocks, index, "diagram_{}_{}_{}".format(*cell), surface)
    return blocks


def model_blocks(path, diagrams_at_cells=True, diagrams=True):
    """A model file's lattices, sphere body and diagrams as a vtkMultiBlockDataSet."""
    model = _rayset().Model.load(path)
    info = model.info()
    density = _lattice_image(model.lattice("density"), ["density"])
    _field(density, "unit", "rays")
    flux = _lattice_image(model.lattice("flux"), ["flux", "luminous", "diagram"])
    _field(flux, "unit", info["flux_unit"])
    spheres = model.spheres()
    body = vtkPolyData()
    body.SetPoints(_points(spheres[:, :3]))
    body.SetVerts(_vertices(len(spheres)))
    body.GetPointData().SetScalars(_array(spheres[:, 3], "radius"))
    _field(body, "unit", "mm")
    blocks = vtkMultiBlockDataSet()
    _name_block(blocks, 0, "density", density)
    _name_block(blocks, 1, "flux", flux)
    _name_block(blocks, 2, "spheres", body)
    if diagrams:
        _name_block(blocks, 3, "diagrams", diagram_surfaces(model, diagrams_at_cells))
    _field(blocks, "flux_unit", info["flux_unit"])
    _field(blocks, "total_flux", info["total_flux"])
    return blocks


# ---- The ParaView readers ---------------------------------------------------------------------


class _Reader(VTKPythonAlgorithmBase):
    """A reader of one file name; `_read(path)` makes the output data."""

    def __init__(self, output_type):
        VTKPythonAlgorithmBase.__init__(self, nInputPorts=0, nOutputPorts=1,
                                        outputType=output_type)
        self._path = None

    def _set_path(self, path):
        if path != self._path:
            self._path = path
            self.Modified()

    def RequestData(self, request, inInfo, outInfo):
        if not self._path:
            raise ValueError("rayset_reader: no file name")
        output = self.GetOutputData(outInfo, 0)
        output.ShallowCopy(self._read(self._path))
        return 1


@smproxy.reader(name="raysetRayFileReader", label="rayset Ray File Reader",
                extensions=RAY_EXTENSIONS,
                file_description="Ray files (rayset: TM-25, LightTools, Zemax, SPEOS, CSV)")
class RayFileReader(_Reader):
    def __init__(self):
        _Reader.__init__(self, "vtkPolyData")

    @smproperty.stringvector(name="FileName")
    @smdomain.filelist()
    @smhint.filechooser(extensions=RAY_EXTENSIONS, file_description="Ray files (rayset)")
    def SetFileName(self, path):
        self._set_path(path)

    def _read(self, path):
        return ray_cloud(path)


@smproxy.reader(name="raysetPhotometryReader", label="rayset Photometry Reader",
                extensions=PHOTOMETRY_EXTENSIONS,
                file_description="Photometric solid (rayset: IES LM-63, EULUMDAT)")
class PhotometryReader(_Reader):
    def __init__(self):
        _Reader.__init__(self, "vtkPolyData")
        self._c_step, self._gamma_step = 5.0, 2.5

    @smproperty.stringvector(name="FileName")
    @smdomain.filelist()
    @smhint.filechooser(extensions=PHOTOMETRY_EXTENSIONS,
                        file_description="IES / EULUMDAT (rayset)")
    def SetFileName(self, path):
        self._set_path(path)

    @smproperty.doublevector(name="CStep", label="C Step", default_values=5.0)
    @smdomain.doublerange(min=0.5, max=90)
    def SetCStep(self, degrees):
        if degrees != self._c_step:
            self._c_step = degrees
            self.Modified()

    @smproperty.doublevector(name="GammaStep", label="Gamma Step", default_values=2.5)
    @smdomain.doublerange(min=0.25, max=90)
    def SetGammaStep(self, degrees):
        if degrees != self._gamma_step:
            self._gamma_step = degrees
            self.Modified()

    def _read(self, path):
        return photometric_solid(path, self._c_step, self._gamma_step)


@smproxy.reader(name="raysetModelReader", label="rayset Model Reader",
                extensions=MODEL_EXTENSIONS,
                file_description="Light-source model (rayset: raymodel build)")
class ModelReader(_Reader):
    def __init__(self):
        _Reader.__init__(self, "vtkMultiBlockDataSet")
        self._at_cells = True

    @smproperty.stringvector(name="FileName")
    @smdomain.filelist()
    @smhint.filechooser(extensions=MODEL_EXTENSIONS, file_description="rayset models")
    def SetFileName(self, path):
        self._set_path(path)

    @smproperty.xml("""
        <IntVectorProperty name="DiagramsAtCells" label="Diagrams At Cells"
                           command="SetDiagramsAtCells" number_of_elements="1"
                           default_values="1">
          <BooleanDomain name="bool"/>
          <Documentation>Place each goniometric diagram at its intensity cell, scaled so that
          the largest intensity reaches half a cell; off: centred at the origin, 1 flux
          unit/sr per unit of length, as rayview exports them.</Documentation>
        </IntVectorProperty>""")
    def SetDiagramsAtCells(self, on):
        if bool(on) != self._at_cells:
            self._at_cells = bool(on)
            self.Modified()

    def _read(self, path):
        return model_blocks(path, self._at_cells)
