// A window of one or two panels showing views of inputs, rendered off-screen to a PNG or shown
// interactively (trackball camera, threshold slider for the density lattice, 'p' over the model
// picks the intensity cell whose diagram the right panel shows).
#pragma once

#include "viz/views.h"

#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

#include <optional>
#include <string>
#include <vector>

namespace rayset::viz {

// Where the camera looks from, fitted to the data: azimuth (degrees, about +z from +x) and
// elevation (degrees above the xy plane) of the camera seen from the focal point, zoom > 1
// closer. +z is up on the screen. 2-D views (polar chart, image) use only the zoom.
struct CameraTurn {
    double azimuth = 0, elevation = 0, zoom = 1;
};
// "azimuth,elevation,zoom" (zoom optional); throws rayset::Error otherwise.
CameraTurn parse_camera(const std::string& text);

struct SceneOptions {
    int width = 1200, height = 900;
    std::optional<CameraTurn> camera;  // default: each view's own turn
    bool offscreen = false;
};

struct Panel {
    vtkSmartPointer<vtkRenderer> renderer;
    ViewHandles handles;
};

struct Scene {
    vtkSmartPointer<vtkRenderWindow> window;
    std::vector<Panel> panels;
};

// Points the renderer's camera as `turn` says, or as the view's handles default to.
void place_camera(vtkRenderer* renderer, const ViewHandles& handles,
                  const std::optional<CameraTurn>& turn);

// `view` of `first`; with `second`, the polar view overlays both far fields in one chart and
// every other view puts the second file in a right-hand panel.
Scene build_scene(Input& first, Input* second, View view, const ViewOptions& options,
                  const SceneOptions& scene);
// Renders and writes the window to `path` (through a temporary file renamed into place).
void write_png(Scene& scene, const std::string& path);
// Opens the window and runs the event loop until it is closed. For model views a right-hand
// panel shows the diagram of the cell picked with 'p'.
void interact(Scene& scene, Input& input, View view, const ViewOptions& options);

}  // namespace rayset::viz
