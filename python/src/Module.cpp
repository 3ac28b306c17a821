// The compiled part of the Python package `geocomp` (python/geocomp/__init__.py imports it
// as geocomp._geocomp; docs/python.md).
#include "Bindings.h"

PYBIND11_MODULE(_geocomp, m)
{
  m.doc() = "geocomp's C++ core: cases, engine runs, responses as numpy arrays, metrics, studies (docs/python.md). "
            "SI units, tension positive.";
  geocomp::python::bind_case(m);
  geocomp::python::bind_response(m);
  geocomp::python::bind_run(m);
  geocomp::python::bind_metrics(m);
  geocomp::python::bind_study(m);
}
