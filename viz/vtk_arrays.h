// Small helpers for the named arrays and field data every viz dataset carries, so exported
// files say what their numbers are (units, source file) when ParaView opens them.
#pragma once

#include <vtkDataObject.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkSmartPointer.h>

#include <string>
#include <vector>

namespace rayset::viz {

vtkSmartPointer<vtkDoubleArray> named_doubles(const char* name, int components = 1);
vtkSmartPointer<vtkFloatArray> named_floats(const char* name, int components = 1);

// Field data: a one-string array / a tuple of doubles under `name`.
void set_field_string(vtkDataObject* data, const char* name, const std::string& value);
void set_field_values(vtkDataObject* data, const char* name, const std::vector<double>& values);
// Empty / empty vector when absent.
std::string field_string(vtkDataObject* data, const char* name);
std::vector<double> field_values(vtkDataObject* data, const char* name);

}  // namespace rayset::viz
