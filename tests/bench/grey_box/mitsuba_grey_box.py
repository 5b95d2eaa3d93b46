"""The room of grey_box.pov in Mitsuba 3 (scalar_rgb path tracer, box pixel filter, the disk as
an area light of its radiance): relative RMSE of the image's luminance against a reference of
REFERENCE spp as spp double, the figures box_convergence prints for raytrace.

POV-Ray's frame is left-handed and Mitsuba's right-handed, so this image is the mirror of
raytrace's; the error figures do not depend on it.

Usage: python3 mitsuba_grey_box.py [WIDTH HEIGHT REFERENCE]   (default 160 160 1024)
"""
import math
import sys
import time

import mitsuba as mi
import numpy as np

mi.set_variant("scalar_rgb")
T = mi.ScalarTransform4f


def diffuse_box(lower, upper, reflectance, inward=False):
    lower, upper = np.array(lower, float), np.array(upper, float)
    return {"type": "cube", "flip_normals": inward,
            "to_world": T().translate(((lower + upper) / 2).tolist()).scale(((upper - lower) / 2).tolist()),
            "bsdf": {"type": "diffuse", "reflectance": {"type": "rgb", "value": [reflectance] * 3}}}


def disk_light(radiance):
    """The bench's light: a Lambertian disk (r = 50 mm) on the ceiling facing down."""
    return {"type": "disk",
            "to_world": T().translate([0, 1999, 0]).rotate([1, 0, 0], 90).scale(50),
            "emitter": {"type": "area", "radiance": {"type": "rgb", "value": list(radiance)}}}


def grey_box(width, height, light=None):
    """The room with `light` (a scene-dict entry); by default a 1 W disk_light."""
    if light is None:
        light = disk_light([1.0 / (math.pi * math.pi * 50 ** 2)] * 3)  # W/(mm^2 sr)
    return mi.load_dict({
        "type": "scene",
        "integrator": {"type": "path", "max_depth": -1},
        "sensor": {"type": "perspective", "fov": 90, "fov_axis": "x",
                   "to_world": T().look_at(origin=[0, 1000, -950], target=[0, 700, 0], up=[0, 1, 0]),
                   "film": {"type": "hdrfilm", "width": width, "height": height,
                            "rfilter": {"type": "box"}},
                   "sampler": {"type": "independent"}},
        "room": diffuse_box([-1000, 0, -1000], [1000, 2000, 1000], 0.6, inward=True),
        "floor": diffuse_box([-999, 0, -999], [999, 1, 999], 0.4),
        "block": diffuse_box([-300, 1, -200], [100, 500, 300], 0.6),
        "light": light,
    }, optimize=False)  # merging the room's mesh with the block's would lose its flipped normals


def luminance(image):
    a = np.array(image, dtype=np.float64)
    return a[..., 0] * 0.2126 + a[..., 1] * 0.7152 + a[..., 2] * 0.0722


def main():
    width, height, reference_spp = (int(v) for v in (sys.argv[1:4] or [160, 160, 1024]))
    scene = grey_box(width, height)
    start = time.time()
    reference = luminance(mi.render(scene, spp=reference_spp, seed=1))
    print(f"Mitsuba {mi.__version__} scalar_rgb path, {width} x {height}; reference "
          f"{reference_spp} spp in {time.time() - start:.1f} s")
    print(f"{'spp':>8} {'seconds':>10} {'rel. RMSE':>12} {'without ref noise':>18}")
    spp = 1
    while spp <= reference_spp // 4:
        start = time.time()
        image = luminance(mi.render(scene, spp=spp, seed=2))
        seconds = time.time() - start
        raw = math.sqrt(((image - reference) ** 2).mean()) / reference.mean()
        # The reference's own noise adds spp / reference_spp of the squared error.
        print(f"{spp:8d} {seconds:10.2f} {raw:12.4f} {raw / math.sqrt(1 + spp / reference_spp):18.4f}",
              flush=True)
        spp *= 2


if __name__ == "__main__":
    main()
