// The glue of a unit of a model with constraint rows (the four-bar linkage),
// with the unit's defaults: YAMSC_FMI_UNIT alone.
#include "four_bar.hpp"

#include <yamsc/fmi/unit.hpp>

YAMSC_FMI_UNIT(four_bar::Model)
