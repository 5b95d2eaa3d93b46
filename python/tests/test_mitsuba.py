"""The "rayset" emitter in Mitsuba 3 (scalar variants) against independent truths: the
luminance raytrace's direct-visibility layer gives the same body, Mitsuba's own disk area light
for a Lambertian disk given as rays, and the RGB variant for the spectral one."""

import math
import sys

import numpy as np
import pytest

import rayset
from conftest import ROOT, rayconv, run, tool

sys.path.insert(0, str(ROOT / "tests" / "bench" / "grey_box"))  # the bench's scene

mi = pytest.importorskip("mitsuba", reason="Mitsuba 3 is not installed (pip install mitsuba)")
import rayset.mitsuba  # noqa: E402

# Linear-sRGB luminance weights (the colour convention of the model, lightmodel/srgb.h).
LUMA = np.array([0.2126, 0.7152, 0.0722])
# raytrace's luminance is in cd/m^2: the model's colour is per mm^2 and its Y is lm / 683.
CD_PER_M2 = 683.0 * 1e6


def synthesised_model(data, name, rays, seed, *source):
    """A ray file of `rayconv synth SOURCE...` and the model raymodel builds of it."""
    path = data / f"{name}.tm25ray"
    rayconv("synth", *source, "--rays", rays, "--seed", seed, "-o", path)
    model = data / f"{name}.vdb"
    run(tool("raymodel"), "build", path, "-o", model, "--threads", 2)
    return model


@pytest.fixture(scope="module")
def chips(data):
    """The example's cluster (scripts/example.sh: 39 chips of three colours, 1 W) with 300000
    rays, seed 5."""
    return synthesised_model(data, "chips", 300000, 5, "cluster", "rings=1,6,12,20", "chip=1",
                             "pitch=2", "flux=1", "wavelength=630,530,460")


@pytest.fixture(scope="module")
def white_disk(data):
    """A Lambertian disk of radius 3 mm with a flat spectrum over 400-700 nm: 50000 rays."""
    spectrum = data / "flat.txt"
    spectrum.write_text("400 1\n500 1\n600 1\n700 1\n")
    return synthesised_model(data, "white_disk", 50000, 4, "disk", "radius=3",
                             f"spectrum={spectrum}")


@pytest.fixture(scope="module")
def lambertian_disk(data):
    """A 1 W Lambertian disk of radius 50 mm at 555 nm: 200000 rays, seed 3."""
    return synthesised_model(data, "disk50", 200000, 3, "disk", "radius=50", "flux=1")


def variant(name):
    mi.set_variant(name)
    rayset.mitsuba.register()
    return mi.ScalarTransform4f


def luminance(image) -> np.ndarray:
    return np.asarray(image, dtype=np.float64)[..., :3] @ LUMA


def front_view(model, width, height, spp, seed):
    """A source seen head-on from 40 mm, 30 degrees across, nothing behind it."""
    T = mi.ScalarTransform4f
    scene = mi.load_dict({
        "type": "scene",
        "integrator": {"type": "path", "max_depth": 3},
        "sensor": {"type": "perspective", "fov": 30, "fov_axis": "x",
                   "to_world": T().look_at(origin=[0, 0, 40], target=[0, 0, 0], up=[0, 1, 0]),
                   "film": {"type": "hdrfilm", "width": width, "height": height,
                            "rfilter": {"type": "box"}},
                   "sampler": {"type": "independent"}},
        "chips": rayset.mitsuba.source(model),
    })
    return luminance(mi.render(scene, spp=spp, seed=seed))


def test_register_refuses_jit_variants():
    if "llvm_ad_rgb" not in mi.variants():
        pytest.skip("no llvm variant in this Mitsuba")
    # Setting the variant is enough: the refusal comes before any JIT code runs.
    mi.set_variant("llvm_ad_rgb")
    with pytest.raises(RuntimeError, match="scalar"):
        rayset.mitsuba.register()


def test_body_seen_with_the_luminance_raytrace_gives(chips, tmp_path):
    variant("scalar_rgb")
    mitsuba_mean = front_view(chips, 48, 48, 64, seed=1).mean() * CD_PER_M2
    scene = tmp_path / "front.pov"
    scene.write_text(
        '#version 3.7;\n'
        'global_settings { length_unit "mm" integrator "bidirectional" }\n'
        'camera { location <0, 0, 40> right x up y look_at <0, 0, 0> angle 30 }\n'
        f'ray_source {{ "{chips}" }}\n')
    image = rayset.render(scene, width=48, height=48, passes=64, seed=1,
                          include_paths=[str(chips.parent)])
    direct = image["layers"]["direct_visibility"]
    raytrace_mean = float(np.mean(direct["Y"]))
    print(f"mean luminance: Mitsuba {mitsuba_mean:.6g} cd/m^2, raytrace {raytrace_mean:.6g}")
    assert raytrace_mean > 0
    # Over four seeds each mean varies by 0.11% (standard deviation, measured for both), so 2%,
    # the agreement asked of the emitter, is more than ten joint standard deviations.
    assert mitsuba_mean == pytest.approx(raytrace_mean, rel=0.02)


def test_spectral_variant_gives_the_rgb_luminance(white_disk):
    means = {}
    for name in ("scalar_rgb", "scalar_spectral"):
        variant(name)
        means[name] = np.array([front_view(white_disk, 16, 16, 512, seed=s).mean()
                                for s in range(8)])
    rgb, spectral = means["scalar_rgb"], means["scalar_spectral"]
    joint = math.sqrt(rgb.var(ddof=1) / 8 + spectral.var(ddof=1) / 8)
    print(f"mean: RGB {rgb.mean():.6g}, spectral {spectral.mean():.6g} (joint error {joint:.2g})")
    # Student's t with about 7 degrees of freedom: 4 standard errors is a two-sided 99.5% bound.
    assert abs(spectral.mean() - rgb.mean()) < 4 * joint
    assert joint < 0.01 * rgb.mean()  # the bound is tight enough to mean something


def grey_boxes(lambertian_disk):
    """The bench's grey box (tests/bench/grey_box) lit by the disk's model and by Mitsuba's disk
    area light of its radiance, 16 x 16 pixels."""
    T = variant("scalar_rgb")
    import mitsuba_grey_box as bench  # sets scalar_rgb, as variant() just did

    # The disk on the ceiling facing down: its model turned as the bench's disk is.
    to_world = T().translate([0, 1999, 0]).rotate([1, 0, 0], 90)
    colour = np.array(rayset.Model.load(lambertian_disk).phi_colour())
    radiance = colour / (math.pi * math.pi * 50**2)  # Lambertian: L = phi / (pi area)
    ours = bench.grey_box(16, 16, rayset.mitsuba.source(lambertian_disk, to_world))
    theirs = bench.disk_light(radiance.tolist())
    theirs["bsdf"] = {"type": "diffuse", "reflectance": 0.0}
    return ours, bench.grey_box(16, 16, theirs)


def test_light_tracing_lights_the_grey_box_as_mitsubas_disk_light(lambertian_disk):
    ours, theirs = grey_boxes(lambertian_disk)
    ptracer = mi.load_dict({"type": "ptracer", "max_depth": -1})
    a, b = (np.array([luminance(mi.render(scene, integrator=ptracer, spp=32, seed=s)).mean()
                      for s in range(4)]) for scene in (ours, theirs))
    joint = math.sqrt(a.var(ddof=1) / 4 + b.var(ddof=1) / 4)
    print(f"grey box, light tracing: rayset {a.mean():.6g}, area light {b.mean():.6g} "
          f"(joint error {100 * joint / b.mean():.2f}%)")
    assert joint < 0.015 * b.mean()
    # Student's t with about 6 degrees of freedom: 4 standard errors is a two-sided 99% bound.
    assert abs(a.mean() - b.mean()) < 4 * joint


def test_grey_box_lit_as_by_mitsubas_disk_light(lambertian_disk):
    ours, theirs = grey_boxes(lambertian_disk)
    # Four independent renders of each give every pixel's mean and standard error.
    a = np.array([luminance(mi.render(ours, spp=32, seed=s)) for s in range(4)])
    b = np.array([luminance(mi.render(theirs, spp=32, seed=10 + s)) for s in range(4)])
    joint = np.sqrt(a.var(axis=0, ddof=1) / 4 + b.var(axis=0, ddof=1) / 4)
    z = (a.mean(axis=0) - b.mean(axis=0)) / joint
    mean_error = math.sqrt(a.mean(axis=(1, 2)).var(ddof=1) / 4
                           + b.mean(axis=(1, 2)).var(ddof=1) / 4) / b.mean()
    print(f"grey box mean: rayset {a.mean():.6g}, area light {b.mean():.6g} (joint error "
          f"{100 * mean_error:.2f}%); RMS of the pixels' z {math.sqrt(np.mean(z**2)):.3f}")
    assert mean_error < 0.004  # so that 1% is 2.5 or more standard errors
    assert a.mean() == pytest.approx(b.mean(), rel=0.01)
    # Each z is about Student's t with 6 degrees of freedom: mean z^2 = 1.5, with a standard
    # error of 0.21 over 256 independent pixels. RMS 1.6 (mean z^2 2.56, five standard errors
    # above) fails a systematic difference of about one standard error in every pixel.
    assert math.sqrt(np.mean(z**2)) < 1.6
