"""geocomp from Python: cases, engine runs, responses as numpy arrays, metrics.

The compiled core (geocomp._geocomp, pybind11) reads and validates case files with the
command line's own readers, runs engines in this process and computes the compare layer's
metrics, and runs studies (geocomp.study); geocomp.results reads results files written
earlier with h5py. SI units, tension positive throughout. docs/python.md lists every function with an example.
"""
from ._geocomp import (  # noqa: F401  (the package's interface)
    Case,
    CaseError,
    Response,
    RunError,
    Study,
    StudyCase,
    acoustic_tensor_onset,
    check,
    deviatoric_state,
    engines,
    material_point,
    metrics,
    pair,
    read_case,
    read_study,
    rudnicki_rice,
    rudnicki_rice_from_drucker_prager,
    rudnicki_rice_onset,
    run,
)
from .results import Results, read_results  # noqa: F401
from .studies import SUMMARY_KEYS, StudyCaseResult, StudyResult, study  # noqa: F401

__all__ = [
    "Case", "CaseError", "Response", "Results", "RunError", "SUMMARY_KEYS", "Study", "StudyCase", "StudyCaseResult",
    "StudyResult", "acoustic_tensor_onset", "check", "deviatoric_state", "engines", "material_point",
    "metrics", "pair", "read_case", "read_results", "read_study", "rudnicki_rice",
    "rudnicki_rice_from_drucker_prager", "rudnicki_rice_onset", "run", "study",
]
