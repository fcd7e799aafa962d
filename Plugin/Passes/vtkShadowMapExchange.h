/**
 * @class   vtkShadowMapExchange
 * @brief   What a shadow pass needs from a parallel renderer: its collectives.
 *
 * Where each process renders its own piece of the data (ParaView's ranks under
 * MPI), a caster on one process must shadow receivers on another. A pass given
 * an exchange (vtkAbstractShadowMapPass::SetExchange) asks it, every frame on
 * every process, whether every process renders interactively (warped maps
 * and cascades may then keep their last views, on all of them or none) and whether any
 * process's maps must be re-rendered; if so, every
 * process re-renders all its layers from its own casters and the pass combines
 * them into the nearest surfaces over all processes: the nearest depth of
 * depth maps, the two nearest surfaces of two-surface maps (NearestTwoOf), the
 * nearest light depth of moment maps, from which each process stores, blurs
 * and mipmaps its moments. The views must be the same on every process: give
 * the pass the global bounds (SetSceneBounds); the fits then also see every
 * process's props (AllBoxes). So must the shadowed lights and hardware selections: a
 * frame without shadowed lights, or one a selector renders, makes no
 * collective call, on every process alike. The module knows no
 * communication library; a subclass wraps one (the ParaView plugin's
 * vtkPVShadowMapExchange wraps vtkMultiProcessController).
 */
#ifndef vtkShadowMapExchange_h
#define vtkShadowMapExchange_h

#include "vtkObject.h"
#include "vtkRenderingShadowMapsModule.h" // For export macro

#include <vector> // For MinimumOf

class VTKRENDERINGSHADOWMAPS_EXPORT vtkShadowMapExchange : public vtkObject
{
public:
  vtkTypeMacro(vtkShadowMapExchange, vtkObject);

  /**
   * Called on every process in the same order: true on all of them if `local`
   * is true on any.
   */
  virtual bool AnyOf(bool local) = 0;

  /**
   * Called on every process with arrays of the same size: each element becomes
   * the smallest of that element over the processes. False on failure.
   */
  virtual bool MinimumOf(std::vector<float>& values) = 0;

  /**
   * Called on every process with arrays of the same size: each element becomes
   * the product of that element over the processes (the transmittance maps'
   * colours: what each process's translucent casters let through). The
   * default multiplies nothing and returns false: the pass then keeps each
   * process's transmittance maps as they are, with a warning. False on
   * failure.
   */
  virtual bool ProductOf(std::vector<float>& values);
  /**
   * Called on every process with arrays of the same size: pairs (x, y) of the
   * nearest depth x and the next one behind it y (or 1, far), such as a peeled
   * two-surface map's texels. Each pair becomes the nearest two over the
   * processes, by two MinimumOf calls: x first, then for each process its
   * nearest depth behind that (its x, or its y where its x is the nearest). A
   * depth several processes hold counts once, as peeling one process's
   * surfaces would. Both calls are made even when the first fails. False on
   * failure.
   */
  bool NearestTwoOf(std::vector<float>& pairs);

  /**
   * Called on every process, every frame that has shadowed lights: `boxes`
   * (six values per box: x, y and z ranges, as vtkProp::GetBounds) becomes
   * every process's boxes, in process order. The pass gathers its props'
   * bounds so, for the fits that follow props (tight cascades, warps) to see
   * every process's props as one process would. The default returns false
   * (boxes unchanged): the fits then see the scene bounds alone.
   */
  virtual bool AllBoxes(std::vector<double>& boxes);

protected:
  vtkShadowMapExchange() = default;
  ~vtkShadowMapExchange() override = default;

private:
  vtkShadowMapExchange(const vtkShadowMapExchange&) = delete;
  void operator=(const vtkShadowMapExchange&) = delete;
};

#endif
