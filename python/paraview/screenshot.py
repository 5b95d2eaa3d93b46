"""A ParaView picture of a light-source model's sphere body with rays leaving it, made with the
reader plugin beside this file (docs/gallery/paraview-model-rays.png).

    PYTHONPATH=build/python xvfb-run -a build/paraview/usr/bin/pvpython \\
        python/paraview/screenshot.py MODEL.vdb RAYS.tm25ray OUT.png [--rays 4000]

The spheres are drawn as ParaView's Point Gaussian spheres of their own radius, coloured by
radius; a random sample of the rays as short segments from their origins along their directions,
coloured by wavelength (by flux when the file gives none). scripts/gallery.sh makes the gallery's
picture from the synthetic 39-chip cluster.
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
    parser.add_argument("--rays-shown", type=int, default=4000, dest="shown",
                        help="rays drawn, a random sample of the file's")
    parser.add_argument("--size", default="900x675", help="WIDTHxHEIGHT in pixels")
    args = parser.parse_args()
    width, height = (int(v) for v in args.size.lower().split("x"))

    plugin = {}
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
    ColorBy(spheres, ("POINTS", "radius"))
    radius_colours = GetColorTransferFunction("radius")
    radius_colours.ApplyPreset("Grayscale", True)
    spheres.SetScalarBarVisibility(view, True)
    GetScalarBar(radius_colours, view).Title = "sphere radius (mm)"

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
    segments.ScaleFactor = 0.6 * extent
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
    lines.Opacity = 0.6
    lines.SetScalarBarVisibility(view, True)
    bar = GetScalarBar(ray_colours, view)
    bar.Title = "ray wavelength (nm)" if colour == "wavelength" else f"ray {colour} flux"
    for b in (bar, GetScalarBar(radius_colours, view)):
        b.TitleColor = b.LabelColor = [0.1, 0.1, 0.1]
    GetScalarBar(radius_colours, view).WindowLocation = "Upper Left Corner"

    view.ResetCamera()
    camera = view.GetActiveCamera()
    camera.Elevation(-55)
    camera.Azimuth(25)
    view.ResetCamera()
    camera.Zoom(1.3)
    Render(view)
    SaveScreenshot(args.png, view, ImageResolution=[width, height], CompressionLevel="9")


main()
