#pragma once
// `yamsc batch` and `yamsc batch merge` for Python (python/yamsc/dask.py maps
// the shards of a manifest over a Dask cluster with them): the CLI's own
// functions, so the files they write are the same bytes.
#include <pybind11/pybind11.h>

namespace yamsc::python {

/// Adds batch(), batch_merge() and read_batch_summary() to the module.
void add_batch_functions(pybind11::module_& mod);

} // namespace yamsc::python
