// Shared by the oracle's and the passes' tests of translucent casters: an
// actor coloured by point scalars through a one-entry lookup table with alpha.
#ifndef ColorByTable_h
#define ColorByTable_h

#include "vtkActor.h"
#include "vtkFloatArray.h"
#include "vtkLookupTable.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"

/// Gives the actor's polydata mapper a copy of its input whose points all
/// carry the scalar 1, mapped through a table of the one entry `rgba`.
inline void ColorByOneTableEntry(vtkActor* actor, double r, double g, double b, double a)
{
  auto* mapper = vtkPolyDataMapper::SafeDownCast(actor->GetMapper());
  mapper->Update();
  vtkNew<vtkPolyData> withScalars;
  withScalars->DeepCopy(mapper->GetInput());
  vtkNew<vtkFloatArray> values;
  values->SetNumberOfTuples(withScalars->GetNumberOfPoints());
  values->FillValue(1.0f);
  withScalars->GetPointData()->SetScalars(values);
  vtkNew<vtkLookupTable> table;
  table->SetNumberOfTableValues(1);
  table->SetTableValue(0, r, g, b, a);
  table->SetRange(0.0, 2.0);
  table->Build();
  mapper->SetInputData(withScalars);
  mapper->SetLookupTable(table);
  mapper->UseLookupTableScalarRangeOn();
  mapper->ScalarVisibilityOn();
}

#endif
