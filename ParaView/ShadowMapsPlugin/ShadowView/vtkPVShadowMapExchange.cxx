#include "vtkPVShadowMapExchange.h"

#include "vtkCommunicator.h"
#include "vtkDoubleArray.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkTimerLog.h"

#include <algorithm>

vtkStandardNewMacro(vtkPVShadowMapExchange);

//------------------------------------------------------------------------------
bool vtkPVShadowMapExchange::AnyOf(bool local)
{
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  if (!controller || controller->GetNumberOfProcesses() < 2)
  {
    return local;
  }
  int mine = local ? 1 : 0;
  int any = 0;
  controller->AllReduce(&mine, &any, 1, vtkCommunicator::MAX_OP);
  return any != 0;
}

//------------------------------------------------------------------------------
bool vtkPVShadowMapExchange::MinimumOf(std::vector<float>& values)
{
  return this->Reduce(values, vtkCommunicator::MIN_OP);
}

//------------------------------------------------------------------------------
bool vtkPVShadowMapExchange::ProductOf(std::vector<float>& values)
{
  return this->Reduce(values, vtkCommunicator::PRODUCT_OP);
}

//------------------------------------------------------------------------------
bool vtkPVShadowMapExchange::Reduce(std::vector<float>& values, int operation)
{
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  // Not skipped for an empty array: the other processes would wait for this one.
  if (!controller || controller->GetNumberOfProcesses() < 2)
  {
    return true;
  }
  std::vector<float> reduced(values.size());
  const double started = vtkTimerLog::GetUniversalTime();
  const int ok = controller->AllReduce(
    values.data(), reduced.data(), static_cast<vtkIdType>(values.size()), operation);
  this->SecondsReducing += vtkTimerLog::GetUniversalTime() - started;
  this->BytesReduced += static_cast<double>(values.size() * sizeof(float));
  values.swap(reduced);
  return ok != 0;
}

//------------------------------------------------------------------------------
bool vtkPVShadowMapExchange::AllBoxes(std::vector<double>& boxes)
{
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  if (!controller || controller->GetNumberOfProcesses() < 2)
  {
    return true;
  }
  vtkNew<vtkDoubleArray> mine;
  mine->SetNumberOfComponents(6);
  mine->SetNumberOfTuples(static_cast<vtkIdType>(boxes.size() / 6));
  std::copy(boxes.begin(), boxes.begin() + 6 * mine->GetNumberOfTuples(), mine->GetPointer(0));
  vtkNew<vtkDoubleArray> all;
  // Empty arrays are sent too: every process takes part.
  if (!controller->AllGatherV(mine, all))
  {
    return false;
  }
  const double* values = all->GetPointer(0);
  boxes.assign(values, values + all->GetNumberOfValues());
  return true;
}
