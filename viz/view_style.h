// The look every view shares: white background, dark text, one perceptually uniform colour
// map (viridis), scalar bars on the right of a panel, cube axes titled with their units.
#pragma once

#include <vtkAlgorithmOutput.h>
#include <vtkLookupTable.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

#include <string>

namespace rayset::viz {

inline constexpr double kBackground[3] = {1, 1, 1};
inline constexpr double kText[3] = {0.1, 0.1, 0.1};

// Viridis over [lo, hi] (a degenerate range is widened so the map stays valid).
vtkSmartPointer<vtkLookupTable> colour_map(double lo, double hi);
// A vertical scalar bar in the right tenth of the renderer's viewport.
void add_scalar_bar(vtkRenderer* renderer, vtkScalarsToColors* map, const std::string& title);
// Cube axes over `bounds` (xmin, xmax, ymin, ymax, zmin, zmax) titled "x (unit)" etc.
void add_axes(vtkRenderer* renderer, const double bounds[6], const std::string& unit,
              const std::string& prefix = "");
// A title line at the top left of the renderer's viewport.
void add_title(vtkRenderer* renderer, const std::string& text);
// Lattice cells as cubes of edge `edge` at the points of `cells`, coloured by their scalars.
void add_cell_cubes(vtkRenderer* renderer, vtkAlgorithmOutput* cells, double edge,
                    vtkLookupTable* lut);

}  // namespace rayset::viz
