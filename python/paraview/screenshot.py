"""A ParaView picture of a light-source model's sphere body with rays leaving it, made with the
reader plugin beside this file (docs/gallery/paraview-model-rays.png).

    PYTHONPATH=build/python xvfb-run -a build/paraview/usr/bin/pvpython \\
        python/paraview/screenshot.py MODEL.vdb RAYS.tm25ray OUT.png [--rays-shown 1200]

The spheres are drawn as ParaView's Point Gaussian spheres of their own radius; a random sample
of the rays as short segments from their origins along their directions, coloured by wavelength
(by flux when the file gives none). scripts/gallery.sh makes the gallery's picture from the
synthetic 39-chip cluster.
"""

import argparse
import os

from paraview.simple import (
    ColorBy,
    ExtractBlock,
    GetActiveViewOrCreate,
    GetColorTransferFunction,
    GetScalarBar,
    Glyph,
    LoadPlugin,
    MaskPoints,
    Render,
    SaveScreenshot,
    Show,
)

HERE = os.path.dirname(os.path.abspath(__file__))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("model", help="model file (.vdb) of raymodel build")
    parser.add_argument("rays", help="ray file (any format rayset reads)")
    parser.add_argument("png", help="picture to write")
    parser.add_argument("--rays-shown", type=int, default=1200, dest="shown",
                        help="rays drawn, a random sample of the file's")
    parser.add_argument("--size", default="900x675", help="WIDTHxHEIGHT in pixels")
    args = parser.parse_args()
    width, height = (int(v) for v in args.size.lower().split("x"))

    # The readers' constructors land in this namespace (an empty dict would be taken for none).
    plugin = globals()
    LoadPlugin(os.path.join(HERE, "rayset_reader.py"), ns=plugin)
    view = GetActiveViewOrCreate("RenderView")
    view.ViewSize = [width, height]
    view.Background = [1, 1, 1]
    view.OrientationAxesVisibility = 1
    try:
        view.UseColorPaletteForBackground = 0  # ParaView 5.11: the background set above
    except AttributeError:
        pass

    model = plugin["raysetModelReader"](FileName=args.model)
    model.UpdatePipeline()
    extract = ExtractBlock(Input=model)
    extract.Selectors = ["/Root/spheres"]
    spheres = Show(extract, view)
    spheres.SetRepresentationType("Point Gaussian")
    spheres.ScaleByArray = 1
    spheres.SetScaleArray = ["POINTS", "radius"]
    spheres.ScaleTransferFunction.RescaleTransferFunction(0, 1)
    spheres.ScaleTransferFunction.Points = [0, 0, 0.5, 0, 1, 1, 0.5, 0]
    spheres.GaussianRadius = 1.0
    spheres.ShaderPreset = "Sphere"
    ColorBy(spheres, None)
    spheres.AmbientColor = spheres.DiffuseColor = [0.55, 0.58, 0.65]

    rays = plugin["raysetRayFileReader"](FileName=args.rays)
    rays.UpdatePipeline()
    info = rays.GetDataInformation()
    total = info.GetNumberOfPoints()
    sample = MaskPoints(Input=rays)
    sample.OnRatio = max(1, total // max(1, args.shown))
    sample.MaximumNumberofPoints = args.shown
    sample.RandomSampling = 1
    sample.GenerateVertices = 1
    bounds = info.GetBounds()
    extent = max(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4])
    segments = Glyph(Input=sample, GlyphType="Line")
    segments.OrientationArray = ["POINTS", "direction"]
    segments.ScaleArray = ["POINTS", "No scale array"]
    segments.ScaleFactor = 0.35 * extent
    segments.GlyphMode = "All Points"
    # A line glyph is centred on its point: shift it to start at the ray's origin.
    segments.GlyphTransform.Translate = [0.5, 0, 0]
    lines = Show(segments, view)
    names = [rays.PointData.GetArray(i).GetName()
             for i in range(rays.PointData.GetNumberOfArrays())]
    colour = "wavelength" if "wavelength" in names else names[1]
    ColorBy(lines, ("POINTS", colour))
    ray_colours = GetColorTransferFunction(colour)
    ray_colours.ApplyPreset("Rainbow Uniform", True)
    lines.Opacity = 0.5
    lines.SetScalarBarVisibility(view, True)
    bar = GetScalarBar(ray_colours, view)
    bar.Title = "ray wavelength (nm)" if colour == "wavelength" else f"ray {colour} flux"
    bar.TitleColor = bar.LabelColor = [0.1, 0.1, 0.1]

    Render(view)  # the first render resets the camera: place it after
    # Obliquely from above the emitting side (+z), so that both the body and the rays show.
    centre = [(bounds[2 * a] + bounds[2 * a + 1]) / 2 for a in range(3)]
    view.CameraFocalPoint = centre
    view.CameraPosition = [centre[0] + 0.9 * extent, centre[1] - 1.6 * extent,
                           centre[2] + 1.3 * extent]
    view.CameraViewUp = [0, 0, 1]
    view.ResetCamera()
    view.GetActiveCamera().Zoom(1.6)
    Render(view)
    SaveScreenshot(args.png, view, ImageResolution=[width, height], CompressionLevel="9")
    try:
        from PIL import Image  # python3-pil, which ParaView's matplotlib brings
    except ImportError:
        return
    # 256 colours show this picture alike (flat background, a few hues) at a third of the bytes.
    with Image.open(args.png) as image:
        palette = image.convert("RGB").quantize(256, dither=Image.Dither.NONE)
    palette.save(args.png, optimize=True)


main()
