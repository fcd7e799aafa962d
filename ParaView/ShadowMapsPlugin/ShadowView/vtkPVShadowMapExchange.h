/**
 * @class   vtkPVShadowMapExchange
 * @brief   The shadow passes' collectives over ParaView's processes.
 *
 * vtkShadowMapExchange over vtkMultiProcessController's global controller (the
 * MPI ranks of pvbatch or pvserver): AnyOf and MinimumOf are all-reductions,
 * AllBoxes an all-gather.
 */
#ifndef vtkPVShadowMapExchange_h
#define vtkPVShadowMapExchange_h

#include "vtkParaViewShadowViewModule.h" // For export macro
#include "vtkShadowMapExchange.h"

class VTKPARAVIEWSHADOWVIEW_EXPORT vtkPVShadowMapExchange : public vtkShadowMapExchange
{
public:
  static vtkPVShadowMapExchange* New();
  vtkTypeMacro(vtkPVShadowMapExchange, vtkShadowMapExchange);

  bool AnyOf(bool local) override;
  bool MinimumOf(std::vector<float>& values) override;
  bool ProductOf(std::vector<float>& values) override;
  bool AllBoxes(std::vector<double>& boxes) override;

  /** Bytes each process sent to MinimumOf and ProductOf over its life (the maps' reductions). */
  vtkGetMacro(BytesReduced, double);

  /** Seconds this process spent in MinimumOf and ProductOf over its life (waiting for the others included). */
  vtkGetMacro(SecondsReducing, double);

protected:
  vtkPVShadowMapExchange() = default;
  ~vtkPVShadowMapExchange() override = default;

private:
  vtkPVShadowMapExchange(const vtkPVShadowMapExchange&) = delete;
  void operator=(const vtkPVShadowMapExchange&) = delete;

  // An all-reduction of `values` by vtkCommunicator's `operation`, timed.
  bool Reduce(std::vector<float>& values, int operation);

  double BytesReduced = 0.0;
  double SecondsReducing = 0.0;
};

#endif
