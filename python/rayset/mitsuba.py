"""The light-source model as a Mitsuba 3 emitter, ``"rayset"``.

Register it once per Mitsuba variant, after ``mi.set_variant``::

    import mitsuba as mi, rayset.mitsuba
    mi.set_variant("scalar_rgb")          # or scalar_spectral
    rayset.mitsuba.register()

The emitter's parameters:

- ``filename``: a model file (``.vdb``, from ``raymodel build``) or a ray file of any format
  rayset reads, built into a model with the default options (or those of ``build_options``, a
  dict of ``raymodel build``'s options as ``rayset.Model.build`` takes them); a process builds
  each file once.
- ``to_world``: the model's frame in the scene. Models are in millimetres; the transform's uniform
  scale is the scene's units per millimetre (``mi.ScalarTransform4f().scale(0.001)`` for a scene
  in metres). Radiance is per scene unit squared and steradian, so that flux is kept.
- ``sampling_weight``: as for every Mitsuba emitter, its share of light sampling (1).

Two ways to place it in a scene:

- On a shape that encloses the source's body and lets light through unchanged (a
  ``dielectric`` of index 1 on both sides; Mitsuba's ``path`` integrator takes no emission
  from a surface with a ``null`` BSDF): the body is seen with its luminance by camera and BSDF
  rays, and light sampling is combined with BSDF sampling by the integrator's multiple
  importance sampling. ``rayset.mitsuba.source(filename, to_world)`` returns such a shape (a
  sphere around the body). The shape must be convex and hold no other surface of the scene; a
  path crossing it spends two bounces of ``max_depth``, and light sampling of other emitters
  does not see through it (their light reaches past it by BSDF sampling alone).
- As an emitter of the scene, without a shape: the source lights the scene through light
  sampling alone and its body is not seen (Mitsuba renders only shapes and environments); it
  says so in a warning.

Colour. In RGB variants the emitter gives the model's linear-sRGB colour (``Model.phi_colour``:
luminance Y in the renderer's convention 683 lm/W x Y); in spectral variants the radiance at the
path's wavelengths, scaled so that Mitsuba's CIE-Y response of it is that same Y.

Sampling. Mitsuba hands an emitter two uniform numbers where the model asks five (flux cell,
voxel, point in the voxel): the other three are hashed from the two, which keeps the estimate
unbiased and a render reproducible from its seed. Light tracing (``sample_ray``) is given in RGB
variants; in spectral ones it is refused (the photon's wavelengths are not exposed to Python).

Mitsuba calls a Python emitter once per query in scalar variants (the JIT variants trace whole
wavefronts and are not supported), and that call costs: light tracing the tests' grey box takes
about 30 times as long as with Mitsuba's own disk light.
"""

from __future__ import annotations

import os
from typing import Dict, Optional, Tuple

import numpy as np

from . import Model, _rayset

_MODELS: Dict[Tuple, Model] = {}


def load_model(filename: str, build_options: Optional[dict] = None) -> Model:
    """The model of a .vdb file or a ray file, each (file, modification time, options) once."""
    path = os.path.abspath(os.fspath(filename))
    options = dict(build_options or {})
    key = (path, os.stat(path).st_mtime_ns, tuple(sorted(options.items())))
    if key not in _MODELS:
        if path.lower().endswith(".vdb"):
            if options:
                raise ValueError(f"{filename}: build_options apply to ray files, not to models")
            _MODELS[key] = Model.load(path)
        else:
            _MODELS[key] = Model.build(path, **options)
    return _MODELS[key]


def source(filename: str, to_world=None, build_options: Optional[dict] = None,
           margin: float = 1e-3) -> dict:
    """A Mitsuba scene-dict entry: a sphere around the model's body carrying the emitter.

    The sphere is there so that camera and BSDF rays find the body: its BSDF, a dielectric of
    index 1, passes light through unchanged.
    """
    import mitsuba as mi

    model = load_model(filename, build_options)
    lower, upper = (np.array(c, dtype=float) for c in model.bounds)
    radius = float(np.linalg.norm(upper - lower)) / 2 * (1 + margin) + margin
    to_world = to_world if to_world is not None else mi.ScalarTransform4f()
    frame = _Frame(to_world)
    centre = frame.scene_point((lower + upper) / 2)
    emitter = {"type": "rayset", "filename": os.fspath(filename), "to_world": to_world}
    if build_options:
        emitter["build_options"] = build_options
    return {"type": "sphere", "center": centre.tolist(), "radius": radius * frame.scale,
            "emitter": emitter,
            "bsdf": {"type": "dielectric", "int_ior": 1.0, "ext_ior": 1.0}}


def _uniforms(a: float, b: float, count: int):
    """`count` further uniform numbers in [0, 1) hashed from two (splitmix64 of their bits)."""
    state = (int(a * 4294967296.0) << 32) | (int(b * 4294967296.0) & 0xFFFFFFFF)
    out = []
    for _ in range(count):
        state = (state + 0x9E3779B97F4A7C15) & 0xFFFFFFFFFFFFFFFF
        z = state
        z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & 0xFFFFFFFFFFFFFFFF
        z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & 0xFFFFFFFFFFFFFFFF
        z ^= z >> 31
        out.append((z >> 11) * (1.0 / 9007199254740992.0))
    return out


class _Frame:
    """The model's frame in the scene: p_scene = A p_model + t, A a rotation times a scale s."""

    def __init__(self, to_world):
        m = np.array(to_world.matrix, dtype=float)
        self.A, self.t = m[:3, :3], m[:3, 3]
        self.A_inverse = np.linalg.inv(self.A)
        lengths = np.linalg.norm(self.A, axis=0)
        if lengths.max() - lengths.min() > 1e-6 * lengths.max():
            raise ValueError(f"rayset emitter: to_world must scale all axes alike (axis lengths "
                             f"{lengths.tolist()}): radiance is defined for similarity "
                             "transforms only")
        self.scale = float(lengths[0])

    def model_point(self, p) -> np.ndarray:
        """A scene point as a row (1 x 3) in the model's frame."""
        return (self.A_inverse @ (np.array([p[0], p[1], p[2]], dtype=float) - self.t))[None]

    def model_direction(self, d) -> np.ndarray:
        """A scene direction as a unit row (1 x 3) in the model's frame; zero for none."""
        v = self.A_inverse @ np.array([d[0], d[1], d[2]], dtype=float)
        length = np.linalg.norm(v)
        return (v / length if length > 0 and np.isfinite(length) else v * 0.0)[None]

    def scene_point(self, p) -> np.ndarray:
        return self.A @ p + self.t

    def scene_direction(self, d) -> np.ndarray:
        v = self.A @ d
        return v / np.linalg.norm(v)


def register() -> None:
    """Registers the emitter type "rayset" for the Mitsuba variant set now (scalar only)."""
    import drjit as dr
    import mitsuba as mi

    variant = mi.variant()
    if variant is None or not variant.startswith("scalar_"):
        raise RuntimeError(f"rayset.mitsuba: variant {variant!r} is not supported; set a scalar "
                           f"variant (scalar_rgb, scalar_spectral) before register()")
    spectral = mi.is_spectral
    # Mitsuba's spectral sensors weigh radiance by CIE y-bar times this factor.
    spectral_scale = 1.0 / mi.MI_CIE_Y_NORMALIZATION

    class RaysetEmitter(mi.Emitter):
        def __init__(self, props):
            mi.Emitter.__init__(self, props)
            filename = props["filename"]
            build_options = props["build_options"] if "build_options" in props else None
            self.model = load_model(filename, build_options)
            self.frame = _Frame(props["to_world"] if "to_world" in props
                                else mi.ScalarTransform4f())
            self.radiance_scale = 1.0 / self.frame.scale**2
            self.filename = filename
            self.warned = False
            self.m_flags = mi.EmitterFlags.Surface | mi.EmitterFlags.SpatiallyVarying
            self.m_needs_sample_2 = True
            self.m_needs_sample_3 = True

        def _radiance(self, result, i) -> mi.Spectrum:
            """The Spectrum of row i of a query result, in the scene's units."""
            if spectral:
                values = result["spectral"][i] * (spectral_scale * self.radiance_scale)
                return mi.Spectrum([float(v) for v in values])
            c = result["colour"][i] * self.radiance_scale
            return mi.Spectrum(float(c[0]), float(c[1]), float(c[2]))

        def _wavelength_rows(self, wavelengths):
            return np.array([[float(w) for w in wavelengths]]) if spectral else None

        def _L(self, p, d, wavelengths) -> mi.Spectrum:
            """Radiance arriving at scene point p from the body along scene direction d."""
            direction = self.frame.model_direction(d)
            if not direction.any():
                return mi.Spectrum(0.0)
            r = self.model.L(self.frame.model_point(p), direction,
                             wavelengths=self._wavelength_rows(wavelengths))
            return self._radiance(r, 0) if r["hit"][0] else mi.Spectrum(0.0)

        # Emitter interface ----------------------------------------------------------------
        def eval(self, si, active=True):
            if not active or mi.Frame3f.cos_theta(si.wi) <= 0:
                return mi.Spectrum(0.0)
            return self._L(si.p, -si.to_world(si.wi), si.wavelengths)

        def sample_direction(self, it, sample, active=True):
            ds = mi.DirectionSample3f()
            if not active:
                return ds, mi.Spectrum(0.0)
            ref = self.frame.model_point(it.p)
            cell, voxel, depth = _uniforms(float(sample[0]), float(sample[1]), 3)
            u = np.array([[cell, voxel, float(sample[0]), float(sample[1]), depth]])
            s = self.model.sample_Li(ref, u,
                                     wavelengths=self._wavelength_rows(it.wavelengths))
            if not s["valid"][0] or not s["pdf"][0] > 0:
                return ds, mi.Spectrum(0.0)
            w = mi.Vector3f(*self.frame.scene_direction(s["wi"][0]))
            body = mi.Point3f(*self.frame.scene_point(ref[0] + s["wi"][0] * s["distance"][0]))
            ds.d, ds.time, ds.emitter = w, it.time, self
            ds.pdf = float(s["pdf"][0])
            entry = self._entry(it.p, w)
            if entry is None:
                # No shape to meet on the way (a scene emitter) or the point is inside it: this
                # direction is found by light sampling alone.
                ds.p, ds.n, ds.delta = body, -w, True
                ds.dist = float(dr.norm(body - it.p))
            else:
                ds.p, ds.n, ds.delta = entry
                ds.dist = float(dr.norm(ds.p - it.p))
            weight = self._radiance(s, 0) / ds.pdf
            return ds, weight

        def _entry(self, p, w):
            """Where a ray from p along w enters the shape carrying the emitter, or None."""
            shape = self.get_shape()
            if shape is None:
                if not self.warned:
                    mi.Log(mi.LogLevel.Warn,
                           f"rayset emitter {self.filename}: not on a shape, its body is not "
                           "visible (rayset.mitsuba.source() makes one)")
                    self.warned = True
                return None
            si = shape.ray_intersect(mi.Ray3f(p, w))
            if not si.is_valid() or dr.dot(si.n, w) >= 0:
                return None
            return si.p, si.n, False

        def pdf_direction(self, it, ds, active=True):
            direction = self.frame.model_direction(ds.d)
            if not active or ds.delta or not direction.any():
                return 0.0
            return float(self.model.pdf_Li(self.frame.model_point(it.p), direction)[0])

        def eval_direction(self, it, ds, active=True):
            if not active:
                return mi.Spectrum(0.0)
            return self._L(it.p, ds.d, it.wavelengths)

        def sample_ray(self, time, wavelength_sample, sample2, sample3, active=True):
            if spectral:
                raise RuntimeError("rayset emitter: light tracing (sample_ray) is not available "
                                   "in spectral variants; use an RGB variant")
            extra = _uniforms(float(sample2[0]), float(sample3[0]), 2)
            u = np.array([[float(wavelength_sample), extra[0], float(sample2[0]),
                           float(sample2[1]), extra[1], float(sample3[0]), float(sample3[1])]])
            s = self.model.sample_Le(u)
            ray = mi.Ray3f(mi.Point3f(*self.frame.scene_point(s["origin"][0])),
                           mi.Vector3f(*self.frame.scene_direction(s["direction"][0])), time)
            c = s["colour"][0]
            return ray, mi.Spectrum(float(c[0]), float(c[1]), float(c[2]))

        def sample_position(self, time, sample, active=True):
            # Light tracing's direct view of the body: a point on the enclosing shape, uniform in
            # area; eval() gives the radiance the body sends through it toward the camera.
            ps = self._shape("light tracing").sample_position(time, sample)
            return ps, mi.Float(1.0 / ps.pdf if ps.pdf > 0 else 0.0)

        def pdf_position(self, ps, active=True):
            return self._shape("light tracing").pdf_position(ps)

        def sample_wavelengths(self, si, sample, active=True):
            # Light tracing's direct view: the radiance that leaves si.p toward si.wi (a scene
            # direction, toward the camera), which is what the body sends through that point.
            if spectral:
                raise RuntimeError("rayset emitter: light tracing is not available in spectral "
                                   "variants; use an RGB variant")
            if not active:
                return si.wavelengths, mi.Spectrum(0.0)
            return si.wavelengths, self._L(si.p, -si.wi, si.wavelengths)

        def _shape(self, purpose):
            shape = self.get_shape()
            if shape is None:
                raise RuntimeError(f"rayset emitter {self.filename}: {purpose} needs the emitter "
                                   "on a shape around the body (rayset.mitsuba.source())")
            return shape

        def bbox(self):
            lower, upper = self.model.bounds
            box = mi.ScalarBoundingBox3f()
            for x in (lower[0], upper[0]):
                for y in (lower[1], upper[1]):
                    for z in (lower[2], upper[2]):
                        box.expand(mi.ScalarPoint3f(*self.frame.scene_point(
                            np.array([x, y, z]))))
            return box

        def to_string(self):
            return f"RaysetEmitter[filename={self.filename}]"

    mi.register_emitter("rayset", lambda props: RaysetEmitter(props))
    _rayset.set_leak_warnings(False)  # Mitsuba's registry outlives the interpreter
