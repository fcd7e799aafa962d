#include "vtkShadowMapExchange.h"
