// Interactive mode of a scene: trackball camera, the density threshold slider, and picking an
// intensity cell over a model view to see its goniometric diagram beside it.
#include "viz/diagram_surface.h"
#include "viz/scene.h"
#include "viz/view_style.h"

#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkCellPicker.h>
#include <vtkCommand.h>
#include <vtkInteractorStyleImage.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkSliderRepresentation2D.h>
#include <vtkSliderWidget.h>
#include <vtkTextProperty.h>

#include <fmt/format.h>
#include <algorithm>
#include <cmath>
#include <iostream>

namespace rayset::viz {

namespace {

struct PickState {
    Input* input = nullptr;
    ViewOptions options;
    vtkRenderer* model_panel = nullptr;
    vtkRenderer* diagram_panel = nullptr;
    vtkCellPicker* picker = nullptr;
};

void show_diagram(PickState& s, const lightmodel::Coord& cell) {
    ViewOptions o = s.options;
    o.cell = cell;
    s.diagram_panel->RemoveAllViewProps();
    const ViewHandles h = add_view(s.diagram_panel, *s.input, View::diagram, o);
    place_camera(s.diagram_panel, h, std::nullopt);
}

void on_pick(vtkObject*, unsigned long, void* data, void*) {
    auto& s = *static_cast<PickState*>(data);
    if (s.picker->GetCellId() < 0) return;
    double p[3];
    s.picker->GetPickPosition(p);
    const auto& model = s.input->model();
    const lightmodel::Coord cell = model.intensity_frame.cell_of({p[0], p[1], p[2]});
    if (diagram_index(model, cell) < 0) {
        std::cerr << fmt::format("intensity cell {},{},{} emits nothing\n", cell[0], cell[1],
                                 cell[2]);
        return;
    }
    std::cerr << fmt::format("picked ({:.3f}, {:.3f}, {:.3f}) mm: intensity cell {},{},{}\n", p[0],
                             p[1], p[2], cell[0], cell[1], cell[2]);
    show_diagram(s, cell);
    s.diagram_panel->GetRenderWindow()->Render();
}

void on_slide(vtkObject* caller, unsigned long, void* data, void*) {
    auto* widget = static_cast<vtkSliderWidget*>(caller);
    const double value =
        static_cast<vtkSliderRepresentation2D*>(widget->GetRepresentation())->GetValue();
    (*static_cast<std::function<void(double)>*>(data))(std::round(value));
}

vtkSmartPointer<vtkSliderWidget> threshold_slider(vtkRenderWindowInteractor* interactor,
                                                  vtkRenderer* renderer, const ViewHandles& h,
                                                  double initial) {
    auto rep = vtkSmartPointer<vtkSliderRepresentation2D>::New();
    rep->SetMinimumValue(h.threshold_min);
    rep->SetMaximumValue(h.threshold_max);
    rep->SetValue(std::clamp(initial, h.threshold_min, h.threshold_max));
    rep->SetTitleText("threshold (rays per voxel)");
    rep->GetPoint1Coordinate()->SetCoordinateSystemToNormalizedViewport();
    rep->GetPoint1Coordinate()->SetValue(0.1, 0.06);
    rep->GetPoint2Coordinate()->SetCoordinateSystemToNormalizedViewport();
    rep->GetPoint2Coordinate()->SetValue(0.7, 0.06);
    rep->SetRenderer(renderer);
    for (auto* p : {rep->GetTitleProperty(), rep->GetLabelProperty()})
        p->SetColor(kText[0], kText[1], kText[2]);
    auto slider = vtkSmartPointer<vtkSliderWidget>::New();
    slider->SetInteractor(interactor);
    slider->SetRepresentation(rep);
    slider->SetAnimationModeToJump();
    slider->SetCurrentRenderer(renderer);
    slider->EnabledOn();
    return slider;
}

}  // namespace

void interact(Scene& scene, Input& input, View view, const ViewOptions& options) {
    auto interactor = vtkSmartPointer<vtkRenderWindowInteractor>::New();
    interactor->SetRenderWindow(scene.window);
    const bool flat = scene.panels.front().handles.flat;
    if (flat)
        interactor->SetInteractorStyle(vtkSmartPointer<vtkInteractorStyleImage>::New());
    else
        interactor->SetInteractorStyle(vtkSmartPointer<vtkInteractorStyleTrackballCamera>::New());

    PickState pick;
    auto picker = vtkSmartPointer<vtkCellPicker>::New();
    auto pick_callback = vtkSmartPointer<vtkCallbackCommand>::New();
    const bool model_view =
        input.kind() == InputKind::model && view != View::diagram && scene.panels.size() == 1;
    if (model_view) {
        // The model keeps the left two thirds; the diagram of the picked cell the rest.
        Panel& left = scene.panels.front();
        left.renderer->SetViewport(0, 0, 0.62, 1);
        auto right = vtkSmartPointer<vtkRenderer>::New();
        right->SetBackground(kBackground[0], kBackground[1], kBackground[2]);
        right->SetViewport(0.62, 0, 1, 1);
        scene.window->AddRenderer(right);
        pick = {&input, options, left.renderer, right, picker};
        show_diagram(pick, chosen_cell(input.model(), options));
        picker->SetTolerance(0.002);
        interactor->SetPicker(picker);
        pick_callback->SetCallback(on_pick);
        pick_callback->SetClientData(&pick);
        picker->AddObserver(vtkCommand::EndPickEvent, pick_callback);
        std::cerr << "press 'p' over the model to show the goniometric diagram of the intensity "
                     "cell there\n";
    }

    vtkSmartPointer<vtkSliderWidget> slider;
    auto slide_callback = vtkSmartPointer<vtkCallbackCommand>::New();
    std::function<void(double)> set_threshold;
    if (scene.panels.front().handles.set_threshold) {
        set_threshold = scene.panels.front().handles.set_threshold;
        slider = threshold_slider(interactor, scene.panels.front().renderer,
                                  scene.panels.front().handles, options.density_threshold);
        slide_callback->SetCallback(on_slide);
        slide_callback->SetClientData(&set_threshold);
        slider->AddObserver(vtkCommand::InteractionEvent, slide_callback);
    }
    scene.window->Render();
    interactor->Initialize();
    interactor->Start();
}

}  // namespace rayset::viz
