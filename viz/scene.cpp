#include "viz/scene.h"
#include "core/geometry.h"

#include "converters/rays/io.h"
#include "core/error.h"
#include "viz/view_style.h"

#include <vtkCamera.h>
#include <vtkPNGWriter.h>
#include <vtkWindowToImageFilter.h>

#include <cmath>
#include <sstream>

namespace rayset::viz {

CameraTurn parse_camera(const std::string& text) {
    std::vector<double> values;
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, ',')) {
        try {
            size_t used = 0;
            values.push_back(std::stod(item, &used));
            if (used != item.size()) throw std::invalid_argument(item);
        } catch (const std::exception&) {
            throw Error("--camera: '" + text + "' is not azimuth,elevation[,zoom] in degrees");
        }
    }
    if (values.size() < 2 || values.size() > 3 || (values.size() == 3 && !(values[2] > 0)))
        throw Error("--camera: '" + text + "' is not azimuth,elevation[,zoom] (zoom > 0)");
    return {values[0], values[1], values.size() == 3 ? values[2] : 1};
}

void place_camera(vtkRenderer* renderer, const ViewHandles& handles,
                  const std::optional<CameraTurn>& turn) {
    vtkCamera* camera = renderer->GetActiveCamera();
    const CameraTurn t = turn ? *turn : CameraTurn{handles.azimuth, handles.elevation, 1};
    if (handles.flat) {
        camera->ParallelProjectionOn();
        camera->SetPosition(0, 0, 1);
        camera->SetViewUp(0, 1, 0);
    } else {
        // Camera direction from the focal point: azimuth about +z from +x, elevation above the
        // xy plane; +z stays up on the screen (LED sources emit along +z) except looking along it.
        const double deg = kRadiansPerDegree, az = t.azimuth * deg, el = t.elevation * deg;
        camera->SetPosition(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el));
        if (std::abs(std::cos(el)) < 1e-3)
            camera->SetViewUp(-std::sin(az), std::cos(az), 0);
        else
            camera->SetViewUp(0, 0, 1);
    }
    camera->SetFocalPoint(0, 0, 0);
    renderer->ResetCamera();
    camera->Zoom(t.zoom);
    renderer->ResetCameraClippingRange();
}

namespace {

Panel make_panel(vtkRenderWindow* window, double x0, double x1) {
    Panel p;
    p.renderer = vtkSmartPointer<vtkRenderer>::New();
    p.renderer->SetBackground(kBackground[0], kBackground[1], kBackground[2]);
    p.renderer->SetViewport(x0, 0, x1, 1);
    window->AddRenderer(p.renderer);
    return p;
}

}  // namespace

Scene build_scene(Input& first, Input* second, View view, const ViewOptions& options,
                  const SceneOptions& so) {
    Scene scene;
    scene.window = vtkSmartPointer<vtkRenderWindow>::New();
    scene.window->SetOffScreenRendering(so.offscreen ? 1 : 0);
    scene.window->SetSize(so.width, so.height);
    scene.window->SetWindowName(("rayview " + first.label()).c_str());
    scene.window->SetMultiSamples(so.offscreen ? 0 : 4);
    const bool overlay = second && view == View::polar;
    if (overlay) {
        Panel p = make_panel(scene.window, 0, 1);
        p.handles = add_polar_view(p.renderer, {&first.intensity(), &second->intensity()});
        scene.panels.push_back(p);
    } else {
        Panel p = make_panel(scene.window, 0, second ? 0.5 : 1);
        p.handles = add_view(p.renderer, first, view, options);
        scene.panels.push_back(p);
        if (second) {
            Panel q = make_panel(scene.window, 0.5, 1);
            q.handles = add_view(q.renderer, *second, view, options);
            scene.panels.push_back(q);
        }
    }
    for (auto& p : scene.panels) place_camera(p.renderer, p.handles, so.camera);
    return scene;
}

void write_png(Scene& scene, const std::string& path) {
    scene.window->Render();
    auto grab = vtkSmartPointer<vtkWindowToImageFilter>::New();
    grab->SetInput(scene.window);
    grab->SetInputBufferTypeToRGB();
    grab->ReadFrontBufferOff();
    grab->Update();
    write_atomically(path, [&](const std::string& temporary) {
        auto writer = vtkSmartPointer<vtkPNGWriter>::New();
        writer->SetFileName(temporary.c_str());
        writer->SetInputConnection(grab->GetOutputPort());
        writer->Write();
        return writer->GetErrorCode() == 0;
    });
}

}  // namespace rayset::viz
