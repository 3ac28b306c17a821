"""geocomp.study: a study file run in this process, as `geocomp study` runs it.

Why it exists: `geocomp study <study.prm>` (docs/studies.md) runs a family of cases and
writes one report; a Python user wants the same run and its numbers as arrays, to plot or
test a trend without parsing the report. The run is the command line's own code
(run_study() of compare/cli/StudyRun.h, through geocomp._geocomp._run_study): the same case
files, the same `pair` on every case (results reused when up to date), the same report
folder with study.json. This module only lays the result out: per case its Responses and
summaries, and the summary table - one row per case and engine - as numpy arrays against
the study's `against` entry. SI units (Pa, strains as fractions, degrees).
"""
import os

import numpy

from . import _geocomp

#: The summary's columns, study.json's keys (compare/StudyReport.h): peak strain, peak
#: stress, secant modulus, elastic limit stress, dilatancy angle, V_r smallest and at the end.
SUMMARY_KEYS = ("peak_strain", "peak_stress_Pa", "secant_modulus_Pa", "elastic_limit_stress_Pa",
                "dilatancy_angle_deg", "V_r_min", "V_r_final")


class StudyCaseResult:
    """One case of a study after the run.

    Attributes: name, label, x (the value of `against`), folder, file (the case file the
    study wrote), status ('complete' or 'failed: <why>'), exit_code (0 ok, 1 failed,
    2 refused), responses {engine: geocomp.Response} (its results files), summaries
    {engine: dict} (study.json's numbers under its keys, plus 'metrics', the full
    geocomp.metrics() dict of the report's curve, and 'error').
    """

    def __init__(self, d):
        for key in ("name", "label", "x", "folder", "file", "status", "exit_code", "responses", "summaries"):
            setattr(self, key, d[key])

    def __repr__(self):
        return "<geocomp.StudyCaseResult %s: %s, %s>" % (self.name, self.label, self.status)


class StudyResult:
    """What geocomp.study returns.

    Attributes: study (the geocomp.Study run), cases (StudyCaseResults, in the study's
    order), summary (dict of numpy arrays, one row per case and engine in that order:
    'case' and 'engine' names, 'x', and SUMMARY_KEYS; NaN where a quantity is missing),
    report (the path of <output>/report/index.html), json (study.json's path), plots_made,
    complete (every case ran its program to the end).
    """

    def __init__(self, study, d):
        self.study = study
        self.cases = [StudyCaseResult(c) for c in d["cases"]]
        self.report, self.json = d["report"], d["json"]
        self.plots_made, self.complete = d["plots_made"], d["complete"]
        rows = [(c, engine, s) for c in self.cases for engine, s in c.summaries.items()]
        self.summary = {
            "case": numpy.array([c.name for c, _, _ in rows], dtype=object),
            "engine": numpy.array([engine for _, engine, _ in rows], dtype=object),
            "x": numpy.array([c.x for c, _, _ in rows], dtype=float),
        }
        for key in SUMMARY_KEYS:
            self.summary[key] = numpy.array([s[key] for _, _, s in rows], dtype=float)

    def summary_of(self, engine):
        """The summary rows of one engine ('dem', 'material-point', ...), by increasing x."""
        keep = self.summary["engine"] == engine
        order = numpy.argsort(self.summary["x"][keep], kind="stable")
        return {key: values[keep][order] for key, values in self.summary.items()}

    def __repr__(self):
        return "<geocomp.StudyResult %s: %d case(s), %s>" % (
            self.study.file, len(self.cases), "complete" if self.complete else "a case failed")


def study(path_or_study, force=False, progress=None):
    """Runs a study file (or a geocomp.Study) as `geocomp study` does; returns a StudyResult.

    The study is read and every case checked first (CaseError naming the study file and its
    parameter); its output folder is locked for the run; each case file is written, each
    case runs through `pair` (results reused when made from the same case by the same build,
    unless force=True), and <output>/report is written (index.html, study.json, plots).
    progress(p) is called at every sample with run()'s dict plus 'engine', 'case',
    'case_index' and 'case_count'; an exception it raises (or Ctrl-C) stops the case that
    runs, every later case at its first sample, and is raised again. A case that fails does
    not raise: its status says why (the report lists it). Starts MPI in this process once
    (one rank; cases run one after another); the GIL is released while it runs.
    """
    s = path_or_study if isinstance(path_or_study, _geocomp.Study) else _geocomp.read_study(os.fspath(path_or_study))
    return StudyResult(s, _geocomp._run_study(s, force, progress))
