// Goniometric-diagram view: a cell's polar surface is drawn exactly as a photometric solid is
// (coloured by intensity, axes in intensity units), so it shares that view.
#include "viz/views.h"

namespace rayset::viz {

ViewHandles add_diagram_view(vtkRenderer* renderer, vtkPolyData* diagram,
                             const std::string& title) {
    return add_farfield_view(renderer, diagram, title);
}

}  // namespace rayset::viz
