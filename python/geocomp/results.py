"""A results file written earlier (docs/results-format.md), read with h5py.

Why it exists: a results file is plain HDF5, and a Python user should not need the
compiled module to plot one. read_results() gives the same array names as the in-memory
geocomp.Response (time, strain, log_strain, stress, stress_mean, volumetric_strain,
gamma_max, tau_max, mean_stress, stage, branch, extras), read into memory (h5py copies
each dataset into a numpy array; the file is closed on return). SI units, tension positive.
"""
import numpy

_COLUMNS = ("time", "strain", "log_strain", "stress", "stress_mean", "volumetric_strain",
            "gamma_max", "tau_max", "mean_stress", "stage", "branch")
_BRANCH_COLUMNS = ("id", "stage", "trigger", "first_sample", "last_sample", "tau_start",
                   "tau_target", "gamma_start", "residual_gamma", "reached_target")


def _text(value):
    """An HDF5 string (attribute, or a one-element dataset) as str."""
    if isinstance(value, numpy.ndarray):
        value = value.reshape(-1)[0] if value.size else b""
    return value.decode("utf-8") if isinstance(value, bytes) else str(value)


def _strings(dataset):
    return [_text(v) for v in dataset[()]] if dataset.shape else []


class Results:
    """One engine's results file: the /response columns as numpy arrays, /meta as a dict.

    Attributes: the columns (see the module docstring), extras (dict name -> array),
    extra_units (dict name -> units), stage_names, stage_end_reasons, branches (list of
    dicts, the /branches columns), meta (the /meta attributes, plus case_text, status,
    parameters, specimen_record where present), engine, status, path.
    """

    def __init__(self, path):
        import h5py  # here, so that `import geocomp` works where h5py is not installed

        self.path = str(path)
        with h5py.File(self.path, "r") as f:
            response = f["response"]
            for name in _COLUMNS:
                setattr(self, name, response[name][()])
            self.extras, self.extra_units = {}, {}
            if "extras" in response:
                for name, dataset in response["extras"].items():
                    self.extras[name] = dataset[()]
                    self.extra_units[name] = _text(dataset.attrs.get("units", ""))
            self.meta = {key: _text(value) if isinstance(value, (bytes, str)) else value
                         for key, value in f["meta"].attrs.items()}
            for name in ("case_text", "status", "parameters", "specimen_record"):
                if name in f["meta"]:
                    self.meta[name] = _text(f["meta"][name][()])
            self.stage_names = _strings(f["stages/name"]) if "stages/name" in f else []
            self.stage_end_reasons = _strings(f["stages/end_reason"]) if "stages/end_reason" in f else []
            self.branches = self._branches(f.get("branches"))
        self.engine = self.meta.get("engine", "")
        self.status = self.meta.get("status", "complete")

    @staticmethod
    def _branches(group):
        if group is None or "id" not in group:
            return []
        columns = {}
        for name in _BRANCH_COLUMNS:
            if name in group:
                columns[name] = _strings(group[name]) if name == "trigger" else group[name][()].tolist()
        if "reached_target" in columns:
            columns["reached_target"] = [bool(v) for v in columns["reached_target"]]
        return [dict(zip(columns, row)) for row in zip(*columns.values())]

    def __len__(self):
        return len(self.time)

    def __repr__(self):
        return f"<geocomp.Results {self.engine}, {len(self)} samples, {self.status}: {self.path}>"


def read_results(path):
    """Reads a results file (<output>/<engine>.h5) with h5py; returns a Results."""
    return Results(path)
