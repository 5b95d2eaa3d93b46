"""rayset from Python: ray files, photometry, light-source models and the renderer.

The work is done by rayset's C++ libraries (the module rayset._rayset); this package gives their
results as numpy arrays:

- ray files: read_rays(), RayReader(...).chunks(n) for files larger than memory, write_rays() and
  RayWriter in any format rayset writes (tm25, lighttools, lighttools-text, zemax, zemax-text,
  speos, csv);
- photometry: read_photometry(), write_photometry(), far_field() (what `rayconv farfield` does);
- models: Model.build(), Model.load(), model.save() and the emitter interface over arrays;
- render(): a scene file rendered as `raytrace` renders it.

Errors in files raise rayset.Error (a RuntimeError) with the C++ message, which names the file
and the byte offset or line.
"""

from __future__ import annotations

import os
from typing import Iterator, Mapping, Optional

import numpy as np

from . import _rayset
from ._rayset import (  # noqa: F401  (re-exported)
    Error,
    FarField,
    Model,
    Photometry,
    detect_photometry_format,
    detect_ray_format,
    far_field,
    read_photometry,
    render,
    write_photometry,
)

__all__ = [
    "Error", "Rays", "RayReader", "RayWriter", "read_rays", "write_rays", "detect_ray_format",
    "Photometry", "FarField", "read_photometry", "write_photometry", "detect_photometry_format",
    "far_field", "Model", "render",
]

_COLUMNS = ("origin", "direction", "radiant", "luminous", "wavelength", "spectrum", "extra")

# What a ray holds for a value its file does not carry (converters/rays/ray.h).
_ABSENT = {"radiant": np.float32(np.nan), "luminous": np.float32(np.nan),
           "wavelength": np.float32(np.nan), "spectrum": np.int32(-1)}

# Extensions that name one format; ".ray" and ".txt" are used by several.
_EXTENSIONS = {".tm25ray": "tm25", ".dat": "zemax", ".sdf": "zemax", ".csv": "csv"}


class Rays:
    """Rays as numpy arrays, one row per ray, values as the file stores them (float32).

    origin, direction: (N, 3), lengths in header["unit"], directions unit vectors.
    radiant (W), luminous (lm), wavelength (nm): (N,), NaN where the file has no value.
    spectrum: (N,) int32 index into header["spectral_tables"], -1 for none.
    A column the file does not carry at all (header has_radiant, has_luminous false; wavelength
    unless header["spectral"] is "per_ray_wavelength"; spectrum unless it is a table kind) is a
    read-only view of NaN (-1) taking no memory: np.array(column) gives a writable copy.
    extra: (N, E) the per-ray columns header["extras"] names (TM-25 Stokes, tristimulus...).
    header: the file's metadata (a dict; totals as the rays sum after any scaling);
    file_header: the same as the file states it; totals: sums of the rays read; warnings:
    what the reader warned about; first_index: index in the file of the first row.
    """

    __slots__ = _COLUMNS + ("header", "file_header", "totals", "warnings", "first_index")

    def __init__(self, origin, direction, radiant=None, luminous=None, wavelength=None,
                 spectrum=None, extra=None, header=None, file_header=None, totals=None,
                 warnings=(), first_index=0):
        self.origin = np.ascontiguousarray(origin, dtype=np.float32).reshape(-1, 3)
        n = len(self.origin)
        self.direction = np.ascontiguousarray(direction, dtype=np.float32).reshape(n, 3)

        def column(values, dtype, fill):
            if values is None:
                return np.full(n, fill, dtype=dtype)
            values = np.ascontiguousarray(values, dtype=dtype)
            if values.shape != (n,):
                raise ValueError(f"a column of {values.shape} values for {n} rays")
            return values

        self.radiant = column(radiant, np.float32, np.nan)
        self.luminous = column(luminous, np.float32, np.nan)
        self.wavelength = column(wavelength, np.float32, np.nan)
        self.spectrum = column(spectrum, np.int32, -1)
        self.extra = (np.zeros((n, 0), np.float32) if extra is None
                      else np.ascontiguousarray(extra, dtype=np.float32).reshape(n, -1))
        self.header = dict(header or {})
        self.file_header = dict(file_header or self.header)
        self.totals = dict(totals or {})
        self.warnings = list(warnings)
        self.first_index = first_index

    @classmethod
    def _from_dict(cls, d: dict, header: dict, file_header: dict, totals=None, warnings=()):
        rays = cls.__new__(cls)
        n = len(d["origin"])
        for name in _COLUMNS:
            value = d[name]
            if value is None:  # a column the file does not carry: the same value in every ray
                value = np.broadcast_to(_ABSENT[name], (n,))
            setattr(rays, name, value)
        rays.header, rays.file_header = header, file_header
        rays.totals = dict(totals or {})
        rays.warnings = list(warnings)
        rays.first_index = d.get("first_index", 0)
        return rays

    def __len__(self) -> int:
        return len(self.origin)

    def __getitem__(self, rows) -> "Rays":
        """The rays of `rows` (a slice, indices or a boolean mask) with the same header."""
        return Rays(*(getattr(self, name)[rows] for name in _COLUMNS), header=self.header,
                    file_header=self.file_header)

    def __repr__(self) -> str:
        return (f"Rays({len(self)} rays, {self.header.get('format', '?')}, "
                f"unit {self.header.get('unit', '?')})")

    @property
    def radiant_total(self) -> float:
        """Sum of the radiant fluxes, W (float64 sum; NaN rays left out)."""
        return float(np.nansum(self.radiant, dtype=np.float64))

    @property
    def luminous_total(self) -> float:
        """Sum of the luminous fluxes, lm (float64 sum; NaN rays left out)."""
        return float(np.nansum(self.luminous, dtype=np.float64))


def _trust(trust: Optional[str]) -> str:
    if trust not in (None, "header", "rays"):
        raise ValueError("trust must be 'header', 'rays' or None (the format's default)")
    return trust or ""


def read_rays(path, format: Optional[str] = None, trust: Optional[str] = None,
              normalise: bool = False, direction_tolerance: float = 1e-3) -> Rays:
    """Reads a whole ray file into numpy arrays (see Rays), validated as rayconv reads it.

    format: skip detection ("tm25", "lighttools", "zemax", ...). trust: which total wins when
    the file's stated total and its rays disagree ("header" scales the rays, "rays" keeps them;
    None: the format's default). normalise: accept non-unit directions and normalise them.
    The file is read in parts on all cores straight into the arrays.
    """
    d = _rayset.read_rays(os.fspath(path), format, _trust(trust), normalise, direction_tolerance)
    return Rays._from_dict(d, d["header"], d["file_header"], d["totals"], d["warnings"])


class RayReader:
    """A ray file read in chunks, in file order, in memory bounded by the chunk size.

    with rayset.RayReader("big.tm25ray") as reader:
        for rays in reader.chunks(1_000_000):
            ...   # rays: a Rays of up to 10^6 rows; rays.first_index is its place in the file
    reader.totals then holds the sums of every ray read.
    """

    def __init__(self, path, format: Optional[str] = None, trust: Optional[str] = None,
                 normalise: bool = False, direction_tolerance: float = 1e-3):
        self._file = _rayset.RayFile(os.fspath(path), format, _trust(trust), normalise,
                                     direction_tolerance)
        self.header = self._file.header
        self.file_header = self._file.file_header

    def read(self, count: int) -> Optional[Rays]:
        """The next up to `count` rays, or None after the last."""
        d = self._file.read(count)
        if d is None:
            return None
        return Rays._from_dict(d, self.header, self.file_header)

    def chunks(self, count: int = 1 << 20) -> Iterator[Rays]:
        """Yields the rest of the file in Rays of `count` rows (the last one shorter)."""
        while (rays := self.read(count)) is not None:
            yield rays

    __iter__ = chunks

    @property
    def totals(self) -> dict:
        """Sums of the rays read so far: radiant, luminous, rays, zero_flux_rays."""
        return self._file.totals

    @property
    def warnings(self) -> list:
        return self._file.warnings

    @property
    def position(self) -> int:
        """Rays handed out so far."""
        return self._file.position

    def __len__(self) -> int:
        return int(self.header["ray_count"])

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        return False


def _format_for(path: str, format: Optional[str]) -> str:
    if format:
        return format
    extension = os.path.splitext(path)[1].lower()
    if extension in _EXTENSIONS:
        return _EXTENSIONS[extension]
    raise ValueError(f"{path}: cannot tell the format from the name ('{extension}' is used by "
                     "several formats or none): give format= (tm25, lighttools, "
                     "lighttools-text, zemax, zemax-text, speos, csv)")


def _has_values(column: np.ndarray) -> bool:
    return bool(len(column)) and not bool(np.isnan(column).all())


class RayWriter:
    """A ray file written in chunks; the file appears at `path` only when close() completes.

    with rayset.RayWriter("out.tm25ray", header={"unit": "mm"}) as writer:
        for rays in rayset.RayReader("big.tm25ray").chunks():
            writer.write(rays)
    `header` describes the rays (keys as Rays.header); has_radiant and has_luminous default to
    whether the first chunk carries such values. The format follows the name's extension
    unless given.
    """

    def __init__(self, path, format: Optional[str] = None, header: Optional[Mapping] = None):
        self._path = os.fspath(path)
        self._format = _format_for(self._path, format)
        self._header = dict(header or {})
        self._writer = None
        self.dropped: list = []

    def write(self, rays) -> None:
        """Writes a Rays, or a mapping with origin, direction and radiant and/or luminous."""
        if not isinstance(rays, Rays):
            rays = Rays(**{k: rays[k] for k in _COLUMNS if k in rays})
        if self._writer is None:
            header = dict(self._header)
            header.setdefault("has_radiant", _has_values(rays.radiant))
            header.setdefault("has_luminous", _has_values(rays.luminous))
            self._writer = _rayset.RayWriter(self._path, self._format, header)
        self._writer.write(rays.origin, rays.direction, rays.radiant, rays.luminous,
                           rays.wavelength, rays.spectrum, rays.extra)

    def close(self) -> list:
        """Completes the file; returns the header fields the format could not hold."""
        if self._writer is None:
            raise ValueError(f"{self._path}: no rays written")
        self.dropped = self._writer.finish()
        return self.dropped

    def __enter__(self):
        return self

    def __exit__(self, exc_type, *exc):
        if exc_type is None:
            self.close()
        elif self._writer is not None:
            self._writer.abandon()
        return False


def write_rays(path, rays, format: Optional[str] = None,
               header: Optional[Mapping] = None) -> list:
    """Writes rays (a Rays, or a mapping of arrays as Rays holds them) as a ray file.

    format: tm25, lighttools, lighttools-text, zemax, zemax-text, speos or csv; by default from
    the name's extension (.tm25ray, .dat, .sdf, .csv). header: metadata (keys as Rays.header)
    over those of `rays`. Stated totals are written as the header gives them; the relative
    formats (LightTools, Zemax, SPEOS) write the rays' sum when the two disagree. Returns the
    header fields the format could not hold.
    """
    if not isinstance(rays, Rays):
        rays = Rays(**{k: rays[k] for k in _COLUMNS if k in rays})
    merged = {k: v for k, v in rays.header.items() if k != "format"}
    merged.update(header or {})
    merged["ray_count"] = len(rays)
    for key, column in (("has_radiant", rays.radiant), ("has_luminous", rays.luminous)):
        if not (header and key in header):
            merged[key] = _has_values(column)
    writer = RayWriter(path, format, merged)
    with writer:
        writer.write(rays)
    return writer.dropped
