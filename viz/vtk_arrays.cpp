#include "viz/vtk_arrays.h"

#include <vtkFieldData.h>
#include <vtkStringArray.h>

namespace rayset::viz {

vtkSmartPointer<vtkDoubleArray> named_doubles(const char* name, int components) {
    auto a = vtkSmartPointer<vtkDoubleArray>::New();
    a->SetName(name);
    a->SetNumberOfComponents(components);
    return a;
}

vtkSmartPointer<vtkFloatArray> named_floats(const char* name, int components) {
    auto a = vtkSmartPointer<vtkFloatArray>::New();
    a->SetName(name);
    a->SetNumberOfComponents(components);
    return a;
}

void set_field_string(vtkDataObject* data, const char* name, const std::string& value) {
    auto a = vtkSmartPointer<vtkStringArray>::New();
    a->SetName(name);
    a->InsertNextValue(value);
    data->GetFieldData()->AddArray(a);
}

void set_field_values(vtkDataObject* data, const char* name, const std::vector<double>& values) {
    auto a = named_doubles(name);
    for (double v : values) a->InsertNextValue(v);
    data->GetFieldData()->AddArray(a);
}

std::string field_string(vtkDataObject* data, const char* name) {
    auto* a = vtkStringArray::SafeDownCast(data->GetFieldData()->GetAbstractArray(name));
    return a && a->GetNumberOfValues() > 0 ? a->GetValue(0) : std::string();
}

std::vector<double> field_values(vtkDataObject* data, const char* name) {
    std::vector<double> values;
    if (auto* a = data->GetFieldData()->GetArray(name))
        for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
            values.push_back(a->GetComponent(i, 0));
    return values;
}

}  // namespace rayset::viz
